#include "files/distance_job.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "util/error.hpp"
#include "util/input_bytes.hpp"

namespace ncv {
namespace {

std::string shown(const DistanceRecords& r) {
  return input_name(r.path);
}

// The same part, sampling and measurement: what shards of one job share.
void check_same_job(const DistanceRecords& first, const DistanceRecords& other) {
  const bool same = other.mesh_hash == first.mesh_hash &&
                    other.total_samples == first.total_samples &&
                    other.sampling.step == first.sampling.step &&
                    other.sampling.scheme == first.sampling.scheme &&
                    other.reference.hash == first.reference.hash &&
                    other.sign_method == first.sign_method && other.search == first.search;
  if (!same) {
    throw UsageError(
        fmt::format("{} and {} are not shards of one job: they differ in the mesh, "
                    "the sampling, the reference or the sign method",
                    shown(first), shown(other)));
  }
  const std::uint32_t count = first.shard ? first.shard->count : 1;
  if (!other.shard || !first.shard || other.shard->count != count) {
    throw UsageError(fmt::format(
        "{} and {} are not shards of the same split ({} and {})", shown(first), shown(other),
        first.shard ? first.shard->text() : "whole", other.shard ? other.shard->text() : "whole"));
  }
}

// The shards' certificates as one, in shard order; none unless every shard has one.
std::optional<Certificate> merged_certificate(const std::vector<const DistanceRecords*>& shards) {
  std::optional<Certificate> whole = shards.front()->certificate;
  for (std::size_t k = 1; k < shards.size() && whole; ++k) {
    if (!shards[k]->certificate) return std::nullopt;
    whole = merged(*whole, *shards[k]->certificate);
    if (!whole) {
      throw UsageError(
          fmt::format("the certificates of {} and {} do not belong together (another "
                      "--certify width?)",
                      shown(*shards[k - 1]), shown(*shards[k])));
    }
  }
  return whole;
}

// One direction's files as one DistanceSet.
DistanceSet merge_direction(std::vector<DistanceRecords> records, const std::string& samples_path) {
  const std::string direction(name_of(kDirectionNames, records.front().direction));
  if (records.size() == 1 && !records.front().shard) {
    SampleSet samples = load_linked_samples(records.front(), samples_path, false);
    return assemble_distance_set(std::move(records.front()), std::move(samples));
  }
  for (const DistanceRecords& r : records) {
    if (!r.shard) {
      throw UsageError(fmt::format(
          "{} and {} both measure the {} direction; give one file per direction, or every "
          "shard of it",
          shown(records.front()), shown(records.back()), direction));
    }
    check_same_job(records.front(), r);
  }
  const std::uint32_t count = records.front().shard->count;
  std::vector<const DistanceRecords*> by_index(count, nullptr);
  for (const DistanceRecords& r : records) {
    const DistanceRecords*& slot = by_index[r.shard->index];
    if (slot) {
      throw UsageError(fmt::format("{} and {} are both shard {} of the {} direction", shown(*slot),
                                   shown(r), r.shard->text(), direction));
    }
    slot = &r;
  }
  for (std::uint32_t k = 0; k < count; ++k) {
    if (!by_index[k]) {
      throw UsageError(fmt::format("shard {} of the {} direction is missing: give all {} shards",
                                   Shard{k, count}.text(), direction, count));
    }
  }
  const DistanceRecords& first = records.front();
  DistanceSet set;
  set.direction = first.direction;
  set.samples = load_linked_samples(first, {}, true);
  set.reference = first.reference;
  set.sign_method = first.sign_method;
  set.search = first.search;
  set.field.distance.resize(set.samples.sample_count());
  set.field.closest_face.resize(set.samples.sample_count());
  set.certificate = merged_certificate(by_index);
  // The shards' ranges partition the samples (load_distance_records checked each range).
  for (const DistanceRecords* r : by_index) {
    std::copy(r->distance.begin(), r->distance.end(),
              set.field.distance.begin() + static_cast<std::ptrdiff_t>(r->first_sample));
    std::copy(r->closest_face.begin(), r->closest_face.end(),
              set.field.closest_face.begin() + static_cast<std::ptrdiff_t>(r->first_sample));
    set.triangles_tested += r->triangles_tested;
  }
  return set;
}

}  // namespace

PartDistances read_part_distances(const std::vector<std::string>& paths,
                                  const std::string& samples_path) {
  if (paths.empty()) throw UsageError("give the distance files of a part");
  std::vector<DistanceRecords> forward, reverse;
  for (const std::string& path : paths) {
    DistanceRecords records = read_distance_records(path);
    (records.direction == Direction::forward ? forward : reverse).push_back(std::move(records));
  }
  if (!samples_path.empty() && forward.size() + reverse.size() > 1) {
    throw UsageError("--samples names the samples file of a single distance file");
  }
  const std::string forward_name = forward.empty() ? "" : shown(forward.front());
  const std::string reverse_name = reverse.empty() ? "" : shown(reverse.front());
  if (forward.empty()) return {merge_direction(std::move(reverse), samples_path), std::nullopt};
  PartDistances part{merge_direction(std::move(forward), samples_path), std::nullopt};
  if (!reverse.empty()) {
    part.reverse = merge_direction(std::move(reverse), samples_path);
    check_same_part(part.main, forward_name, *part.reverse, reverse_name);
  }
  return part;
}

void check_same_part(const DistanceSet& forward, const std::string& forward_source,
                     const DistanceSet& reverse, const std::string& reverse_source) {
  if (forward.samples.mesh_hash != reverse.reference.hash ||
      forward.reference.hash != reverse.samples.mesh_hash) {
    throw UsageError(fmt::format(
        "{} and {} do not measure the same part: the forward files compare {} with {}, the "
        "reverse ones {} with {}",
        forward_source, reverse_source, forward.samples.source, forward.reference.source,
        reverse.samples.source, reverse.reference.source));
  }
}

}  // namespace ncv
