// The distance files of one part put together: at most one forward and one reverse
// direction, each either one file or every shard of a sharded job, whose records go back into
// the whole lattice's field in sample order: exactly what the unsharded job writes, to the bit.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "files/distance_file.hpp"

namespace ncv {

struct PartDistances {
  DistanceSet main;                    // the forward direction, or the only one given
  std::optional<DistanceSet> reverse;  // when both were given
};

// Throws UsageError for files of different parts or sampling, a direction twice, a shard
// missing or twice; InputError for a file that cannot be read. `samples_path`, when given,
// is the samples file of a single distance file (--samples).
PartDistances read_part_distances(const std::vector<std::string>& paths,
                                  const std::string& samples_path = {});

// Throws UsageError unless `reverse` measures the nominal of `forward` against its workpiece,
// by the meshes' content hashes.
void check_same_part(const DistanceSet& forward, const std::string& forward_source,
                     const DistanceSet& reverse, const std::string& reverse_source);

}  // namespace ncv
