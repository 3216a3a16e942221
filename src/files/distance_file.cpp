#include "files/distance_file.hpp"

#include <cmath>

#include "files/mesh_arrays.hpp"
#include "files/samples_file.hpp"

namespace ncv {
namespace {

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

nlohmann::json distance_meta(const DistanceSet& set) {
  nlohmann::json meta = sample_set_meta(set.samples);
  nlohmann::json reference = {{"source", set.reference.source},
                              {"hash", hash_hex(set.reference.hash)},
                              {"triangles", set.reference.triangles}};
  reference.update(box_json(set.reference.box));
  meta["reference"] = reference;
  meta["distance"] = {{"direction", name_of(kDirectionNames, set.direction)},
                      {"sign_method", set.sign_method},
                      {"search", set.search},
                      {"triangles_tested_per_sample", set.triangles_tested_per_sample}};
  meta["records"]["sections"] = {"positions", "owner",         "lattice_i",   "lattice_j",
                                 "distance",  "closest_point", "closest_face"};
  return meta;
}

}  // namespace

void write_distance_file(const DistanceSet& set, OutputFile& out) {
  const std::uint64_t S = set.samples.sample_count();
  ContainerWriter writer(FileKind::distances, kDistancesFormatVersion, distance_meta(set));
  add_sample_sections(writer, set.samples);
  writer.add<double>("distance", set.field.distance, {S});
  writer.add<double>("closest_point", flat_coordinates(set.field.closest_point), {S, 3});
  writer.add<std::uint32_t>("closest_face", set.field.closest_face, {S});
  writer.write(out);
}

DistanceSet read_distance_file(const std::string& path) {
  return load_distance_set(Container::read(path, FileKind::distances, kDistancesFormatVersion));
}

DistanceSet load_distance_set(const Container& c) {
  DistanceSet set;
  set.samples = load_sample_set(c);
  const std::uint64_t S = set.samples.sample_count();
  set.reference.source = string_field(c, "/reference/source");
  set.reference.hash = parse_hash_hex(string_field(c, "/reference/hash"), c);
  set.reference.triangles = c.count("/reference/triangles");
  set.reference.box = box_from(c, "/reference");
  const auto direction = parse_name(kDirectionNames, string_field(c, "/distance/direction"));
  if (!direction) c.fail("metadata field /distance/direction is neither forward nor reverse");
  set.direction = *direction;
  set.sign_method = string_field(c, "/distance/sign_method");
  set.search = string_field(c, "/distance/search");
  if (!c.field("/distance/triangles_tested_per_sample").is_number()) {
    c.fail("metadata field /distance/triangles_tested_per_sample is not a number");
  }
  set.triangles_tested_per_sample = c.field("/distance/triangles_tested_per_sample").get<double>();

  set.field.distance = c.get<double, Buffer<double>>("distance", S);
  set.field.closest_point = c.get_rows<double, Vec3, Buffer<Vec3>>("closest_point", S);
  set.field.closest_face = c.get<std::uint32_t, Buffer<std::uint32_t>>("closest_face", S);
  for (std::uint64_t s = 0; s < S; ++s) {
    if (!std::isfinite(set.field.distance[s]) || !is_finite(set.field.closest_point[s])) {
      c.fail("a distance or closest point is not finite");
    }
    if (set.field.closest_face[s] >= set.reference.triangles) {
      c.fail("a closest face lies outside the reference surface");
    }
  }
  return set;
}

}  // namespace ncv
