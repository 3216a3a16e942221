// CLI11 validators for the option values ncverify parses itself. A step, a tolerance zone,
// a range or a cell size that does not parse is refused while the command line is read,
// before any input is read or output written: `run` used to sample, build the grid and
// measure (and leave three files behind) before it looked at its --tol.
#pragma once

#include <CLI/CLI.hpp>

namespace ncv::cmd {

CLI::Validator valid_step();             // --step: SamplingStep::parse
CLI::Validator valid_zone();             // --tol: parse_tolerance (a zero-width zone is allowed)
CLI::Validator valid_range();            // --range, --histogram-range: parse_value_range
CLI::Validator valid_positive_length();  // --cell: a finite length above zero
CLI::Validator valid_count();            // --head: a whole number, 0 or more

}  // namespace ncv::cmd
