// The search's coarse level: the background grid with cells twice as large, made in memory
// from the grid itself, for queries far from the reference (closest_point_search.hpp).
//
// A query at distance d reads every cell that meets its ball; with cells of edge h that is
// about (2d/h + 1)^3 cells, most of them empty or listing a triangle its box then rejects.
// Samples far off the nominal (roughing leaves up to 6 mm on a nominal whose cells are 1.9
// mm) pay for those cells; samples on the surface read one cell, whose list grows with h.
//
// Coarse cell (i, j, k) is fine cells 2i..2i+1 by 2j..2j+1 by 2k..2k+1 (those that exist): the
// same origin and twice the cell size, so every coarse bound, origin + i * 2h, is the fine
// bound origin + 2i * h to the last bit (both are 2 * round(i * h)). Its list is the union of
// theirs, ascending: a triangle touching the coarse cell touches one of its fine cells, so the
// lists are as complete as the fine grid's, and the search over them as exact.
#pragma once

#include "search/background_grid.hpp"

namespace ncv {

BackgroundGrid coarsen(const BackgroundGrid& fine);

}  // namespace ncv
