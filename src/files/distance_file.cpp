#include "files/distance_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "geometry/point_json.hpp"
#include "util/input_bytes.hpp"

namespace ncv {
namespace {

namespace fs = std::filesystem;

nlohmann::json box_json(const BoundingBox& box) {
  return {{"bbox_min", {box.min[0], box.min[1], box.min[2]}},
          {"bbox_max", {box.max[0], box.max[1], box.max[2]}}};
}

BoundingBox box_from(const Container& c, const std::string& prefix) {
  BoundingBox box;
  const nlohmann::json& lo = c.field(prefix + "/bbox_min");
  const nlohmann::json& hi = c.field(prefix + "/bbox_max");
  if (!lo.is_array() || !hi.is_array() || lo.size() != 3 || hi.size() != 3) {
    c.fail(prefix + " bounding box is malformed");
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!lo[axis].is_number() || !hi[axis].is_number())
      c.fail(prefix + " bounding box is malformed");
    box.min[axis] = lo[axis].get<double>();
    box.max[axis] = hi[axis].get<double>();
  }
  return box;
}

std::string string_field(const Container& c, const std::string& pointer) {
  const nlohmann::json& value = c.field(pointer);
  if (!value.is_string()) c.fail("metadata field " + pointer + " is not a string");
  return value.get<std::string>();
}

Vec3 point_from(const Container& c, const nlohmann::json& value) {
  if (!value.is_array() || value.size() != 3) c.fail("a certificate point is malformed");
  Vec3 p(0, 0, 0);
  for (int axis = 0; axis < 3; ++axis) {
    if (!value[axis].is_number()) c.fail("a certificate point is malformed");
    p[axis] = value[axis].get<double>();
  }
  return p;
}

double number_from(const Container& c, const nlohmann::json& object, const char* key) {
  if (!object.contains(key) || !object[key].is_number() ||
      !std::isfinite(object[key].get<double>())) {
    c.fail(fmt::format("certificate field {} is not a finite number", key));
  }
  return object[key].get<double>();
}

CertifiedExtreme extreme_from(const Container& c, const nlohmann::json& object) {
  if (!object.is_object() || !object.contains("measured_at") || !object.contains("bound_at")) {
    c.fail("a certificate extreme is malformed");
  }
  return {number_from(c, object, "measured"), point_from(c, object["measured_at"]),
          number_from(c, object, "bound"), point_from(c, object["bound_at"])};
}

nlohmann::json certificate_json(const Certificate& c) {
  return {{"width_asked", c.width_asked},
          {"points_cap", c.points_cap},
          {"max", certified_extreme_json(c.max)},
          {"min", certified_extreme_json(c.min)},
          {"patches", c.patches},
          {"refined_patches", c.refined_patches},
          {"added_points", c.added_points},
          {"unresolved", c.unresolved},
          {"sign_proven", c.sign_proven},
          {"first_anchor", c.first_anchor},
          {"end_anchor", c.end_anchor}};
}

Certificate certificate_from(const Container& c) {
  const nlohmann::json& j = c.meta()["certificate"];
  if (!j.is_object() || !j.contains("sign_proven") || !j["sign_proven"].is_boolean() ||
      !j.contains("max") || !j.contains("min")) {
    c.fail("its certificate is malformed");
  }
  Certificate cert;
  cert.width_asked = number_from(c, j, "width_asked");
  cert.points_cap = c.count("/certificate/points_cap");
  cert.max = extreme_from(c, j["max"]);
  cert.min = extreme_from(c, j["min"]);
  cert.patches = c.count("/certificate/patches");
  cert.refined_patches = c.count("/certificate/refined_patches");
  cert.added_points = c.count("/certificate/added_points");
  cert.unresolved = c.count("/certificate/unresolved");
  cert.sign_proven = j["sign_proven"].get<bool>();
  cert.first_anchor = c.count("/certificate/first_anchor");
  cert.end_anchor = c.count("/certificate/end_anchor");
  if (!(cert.max.bound >= cert.max.measured) || !(cert.min.bound <= cert.min.measured) ||
      cert.first_anchor > cert.end_anchor) {
    c.fail("its certificate is inconsistent");
  }
  return cert;
}

nlohmann::json distance_meta(const DistanceSet& set, const std::optional<SamplesLink>& link) {
  nlohmann::json meta = sample_set_meta(set.samples);
  meta["samples_file"] = link ? nlohmann::json{{"path", link->path}, {"hash", hash_hex(link->hash)}}
                              : nlohmann::json{{"embedded", true}};
  nlohmann::json reference = {{"source", set.reference.source},
                              {"hash", hash_hex(set.reference.hash)},
                              {"triangles", set.reference.triangles}};
  reference.update(box_json(set.reference.box));
  meta["reference"] = reference;
  meta["distance"] = {{"direction", name_of(kDirectionNames, set.direction)},
                      {"sign_method", set.sign_method},
                      {"search", set.search},
                      {"triangles_tested", set.triangles_tested}};
  if (set.certificate) meta["certificate"] = certificate_json(*set.certificate);
  meta["records"] = {{"name", "samples"},
                     {"count", set.samples.sample_count()},
                     {"first", set.samples.first_sample},
                     {"sections", {"distance", "closest_face"}}};
  return meta;
}

// Candidates for a linked samples file, in order: the path the caller gave, the link's path
// from the distance file's folder, the link's path from the current folder.
std::vector<std::string> samples_candidates(const DistanceRecords& r, const std::string& given) {
  if (!given.empty()) return {given};
  const std::string link = string_field(r.container, "/samples_file/path");
  std::vector<std::string> candidates;
  if (r.path != "-" && fs::path(link).is_relative()) {
    candidates.push_back((fs::path(r.path).parent_path() / link).string());
  }
  candidates.push_back(link);
  return candidates;
}

}  // namespace

std::optional<SamplesLink> link_samples(const std::string& samples_path, std::uint64_t hash,
                                        const std::string& distance_path) {
  if (samples_path == "-") return std::nullopt;
  if (distance_path == "-") return SamplesLink{samples_path, hash};
  const fs::path samples = fs::absolute(samples_path).lexically_normal();
  const fs::path folder = fs::absolute(distance_path).parent_path().lexically_normal();
  const fs::path relative = samples.lexically_relative(folder);
  return SamplesLink{(relative.empty() ? samples : relative).string(), hash};
}

void write_distance_file(const DistanceSet& set, const std::optional<SamplesLink>& samples,
                         OutputFile& out) {
  const std::uint64_t S = set.samples.sample_count();
  ContainerWriter writer(FileKind::distances, kDistancesFormatVersion, distance_meta(set, samples));
  if (!samples) add_sample_sections(writer, set.samples);
  writer.add<double>("distance", set.field.distance, {S});
  writer.add<std::uint32_t>("closest_face", set.field.closest_face, {S});
  writer.write(out);
}

DistanceRecords read_distance_records(const std::string& path) {
  return load_distance_records(Container::read(path, FileKind::distances, kDistancesFormatVersion),
                               path);
}

DistanceRecords load_distance_records(Container container, const std::string& path) {
  DistanceRecords r(std::move(container), path);
  const Container& c = r.container;
  const auto direction = parse_name(kDirectionNames, string_field(c, "/distance/direction"));
  if (!direction) c.fail("metadata field /distance/direction is neither forward nor reverse");
  r.direction = *direction;
  r.sampling = sampling_settings(c);
  r.shard = r.sampling.shard;
  r.mesh_hash = parse_hash_hex(string_field(c, "/mesh/hash"), c);
  r.total_samples = c.count("/sampling/samples");
  r.first_sample = c.count("/records/first");
  const std::uint64_t S = c.count("/records/count");
  const SampleRange range =
      r.shard ? shard_range(r.total_samples, *r.shard) : SampleRange{0, r.total_samples};
  if (r.first_sample != range.begin || S != range.size()) {
    c.fail("its records are not the samples of its shard");
  }
  r.reference.source = string_field(c, "/reference/source");
  r.reference.hash = parse_hash_hex(string_field(c, "/reference/hash"), c);
  r.reference.triangles = c.count("/reference/triangles");
  r.reference.box = box_from(c, "/reference");
  r.sign_method = string_field(c, "/distance/sign_method");
  r.search = string_field(c, "/distance/search");
  r.triangles_tested = c.count("/distance/triangles_tested");
  if (c.meta().contains("certificate")) r.certificate = certificate_from(c);
  r.distance = c.get<double, Buffer<double>>("distance", S);
  r.closest_face = c.get<std::uint32_t, Buffer<std::uint32_t>>("closest_face", S);
  for (std::uint64_t s = 0; s < S; ++s) {
    if (!std::isfinite(r.distance[s])) c.fail("a distance is not finite");
    if (r.closest_face[s] >= r.reference.triangles) {
      c.fail("a closest face lies outside the reference surface");
    }
  }
  if (!c.meta().contains("samples_file")) c.fail("it does not say where its samples are");
  return r;
}

SampleSet load_linked_samples(const DistanceRecords& r, const std::string& samples_path,
                              bool whole) {
  const Container& c = r.container;
  SampleSet samples;
  if (c.meta()["samples_file"].contains("embedded")) {
    samples = load_sample_set(c, whole);
  } else {
    const std::uint64_t hash = parse_hash_hex(string_field(c, "/samples_file/hash"), c);
    std::optional<Container> found;
    for (const std::string& candidate : samples_candidates(r, samples_path)) {
      std::error_code error;
      if (!fs::exists(candidate, error)) continue;
      found = Container::read(candidate, FileKind::samples, kSamplesFormatVersion);
      if (found->content_hash() != hash) {
        throw InputError(candidate, fmt::format("is not the samples file {} was measured from "
                                                "(its content differs); sample again",
                                                input_name(r.path)));
      }
      break;
    }
    if (!found) {
      c.fail(fmt::format("its samples file '{}' is not there; give it with --samples",
                         string_field(c, "/samples_file/path")));
    }
    samples = load_sample_set(*found, whole);
  }
  if (samples.mesh_hash != r.mesh_hash || samples.total_samples != r.total_samples) {
    c.fail("its samples file holds another mesh or lattice");
  }
  return samples;
}

DistanceSet assemble_distance_set(DistanceRecords r, SampleSet samples) {
  if (samples.first_sample != r.first_sample || samples.sample_count() != r.distance.size()) {
    r.container.fail("its records do not match its samples");
  }
  DistanceSet set;
  set.direction = r.direction;
  set.samples = std::move(samples);
  set.field.distance = std::move(r.distance);
  set.field.closest_face = std::move(r.closest_face);
  set.reference = std::move(r.reference);
  set.sign_method = std::move(r.sign_method);
  set.search = std::move(r.search);
  set.triangles_tested = r.triangles_tested;
  set.certificate = r.certificate;
  return set;
}

DistanceSet read_distance_file(const std::string& path, const std::string& samples_path) {
  DistanceRecords records = read_distance_records(path);
  SampleSet samples = load_linked_samples(records, samples_path, false);
  return assemble_distance_set(std::move(records), std::move(samples));
}

}  // namespace ncv
