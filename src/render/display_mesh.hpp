// The mesh the HTML report's 3D view draws: the coloured error within a budget of
// triangles, so that the report stays a file a person can e-mail and a browser can turn.
//
// Within the budget the view shows the sampling lattice itself, every sample a vertex
// (as the PLY does). Beyond it, the workpiece's own triangles carry their corner samples,
// and the triangles whose lattice says more than their corners are shown with their whole
// lattice, most telling first, while the budget lasts: first those holding the largest or
// smallest error, then those with an out-of-tolerance sample, then by how far their
// lattice departs from the corners' linear interpolation. A workpiece whose own
// triangles exceed the budget is simplified by vertex clustering with the error's features
// kept: vertices merge only within one cell of a grid, one tolerance class and one band of
// 1/32 of the colour range, and no vertex of an out-of-tolerance region or of a worst
// point merges at all. Every vertex keeps the value of the sample it stands for; no value
// is invented. (OpenMesh's decimater was tried first: on the 1.24 M-triangle finishing part
// it took 394 s, its collapse checks dominating; the clustering takes well under a second.)
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "render/error_mesh.hpp"
#include "sampling/sampling.hpp"
#include "statistics/tolerance.hpp"
#include "statistics/value_range.hpp"

namespace ncv {

// About 10 MB of HTML for a page's views together: a browser loads and turns it at once.
inline constexpr std::uint64_t kDisplayTriangleBudget = 250000;

enum class DisplayDetail {
  every_sample,  // the whole lattice
  refined,       // workpiece triangles, the telling ones with their lattice
  clustered,     // the workpiece's triangles simplified, the features kept
};

struct DisplayMesh {
  ErrorMesh mesh;
  DisplayDetail detail = DisplayDetail::every_sample;
  std::uint64_t lattice_triangles = 0;  // triangles of the whole lattice (every sample)
  std::uint64_t refined_triangles = 0;  // workpiece triangles shown with their lattice
  std::uint64_t budget = 0;
};

struct DisplayMeshInput {
  const SampleSet& samples;
  std::span<const double> d;                     // per sample
  std::span<const std::uint32_t> sample_region;  // per sample, or empty
  std::optional<Tolerance> tolerance;
  ValueRange color_range;  // the colour map's range
};

DisplayMesh make_display_mesh(const DisplayMeshInput& input,
                              std::uint64_t budget = kDisplayTriangleBudget);

// One sentence for the report: what the view shows of the measurement.
std::string describe(const DisplayMesh& display);

}  // namespace ncv
