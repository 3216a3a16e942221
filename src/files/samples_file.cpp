#include "files/samples_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "files/mesh_arrays.hpp"
#include "util/memory_guard.hpp"

namespace ncv {
namespace {

SamplingScheme parse_scheme(const std::string& name, const Container& from) {
  const std::optional<SamplingScheme> scheme = parse_name(kSamplingSchemeNames, name);
  if (!scheme) from.fail(fmt::format("unknown sampling scheme '{}'", name));
  return *scheme;
}

void validate_mesh(const Mesh& mesh, const Container& from) {
  for (const Vec3& v : mesh.vertices) {
    if (!is_finite(v)) from.fail("mesh vertex coordinates are not finite");
  }
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t v : t) {
      if (v >= mesh.vertex_count()) from.fail("mesh triangle refers to a missing vertex");
    }
  }
}

std::optional<Shard> shard_of(const Container& c) {
  if (!c.meta().contains("shard")) return std::nullopt;
  const std::uint64_t index = c.count("/shard/index"), count = c.count("/shard/count");
  if (index < 1 || index > count || count > kMaxShards) c.fail("shard is malformed");
  return Shard{static_cast<std::uint32_t>(index - 1), static_cast<std::uint32_t>(count)};
}

}  // namespace

SamplingSettings sampling_settings(const Container& c) {
  if (!c.field("/mesh/source").is_string()) c.fail("mesh source is malformed");
  if (!c.field("/sampling/step").is_number() || !c.field("/sampling/step_spec").is_string() ||
      !c.field("/sampling/scheme").is_string()) {
    c.fail("sampling parameters are malformed");
  }
  SamplingSettings settings;
  settings.source = c.field("/mesh/source").get<std::string>();
  settings.step = c.field("/sampling/step").get<double>();
  if (!(settings.step > 0) || !std::isfinite(settings.step)) {
    c.fail("sampling step is not positive");
  }
  settings.step_spec = c.field("/sampling/step_spec").get<std::string>();
  settings.scheme = parse_scheme(c.field("/sampling/scheme").get<std::string>(), c);
  settings.shard = shard_of(c);
  return settings;
}

nlohmann::json sample_set_meta(const SampleSet& set) {
  const BoundingBox box = bounding_box(set.mesh);
  nlohmann::json meta = {{"tool", "ncverify " NCV_VERSION},
                         {"mesh",
                          {{"source", set.source},
                           {"hash", hash_hex(set.mesh_hash)},
                           {"vertices", set.mesh.vertex_count()},
                           {"triangles", set.mesh.triangle_count()},
                           {"bbox_min", {box.min[0], box.min[1], box.min[2]}},
                           {"bbox_max", {box.max[0], box.max[1], box.max[2]}}}},
                         {"sampling",
                          {{"step", set.step},
                           {"step_spec", set.step_spec},
                           {"scheme", name_of(kSamplingSchemeNames, set.scheme)},
                           {"samples", set.total_samples}}}};
  if (set.shard) {
    meta["shard"] = {{"index", set.shard->index + 1},
                     {"count", set.shard->count},
                     {"first_sample", set.first_sample},
                     {"samples", set.sample_count()}};
  }
  return meta;
}

void add_sample_sections(ContainerWriter& writer, const SampleSet& set) {
  const std::uint64_t T = set.mesh.triangle_count();
  writer.add_points("mesh_vertices", set.mesh.vertices);
  writer.add<std::uint32_t>("mesh_triangles", flat_indices(set.mesh.triangles), {T, 3});
  // Most triangles of a simulated workpiece are tiny (size 2): a byte each.
  writer.add_counts("lattice_sizes", set.lattice_sizes);
}

SampleSet load_sample_set(const Container& c, bool whole) {
  const std::uint64_t V = c.count("/mesh/vertices"), T = c.count("/mesh/triangles");
  Mesh mesh;
  mesh.vertices = c.get_points("mesh_vertices", V);
  mesh.triangles = c.get_rows<std::uint32_t, Triangle>("mesh_triangles", T);
  validate_mesh(mesh, c);
  if (!c.field("/mesh/hash").is_string()) c.fail("mesh hash is malformed");
  const std::uint64_t hash = parse_hash_hex(c.field("/mesh/hash").get<std::string>(), c);
  if (mesh_hash(mesh) != hash) c.fail("mesh hash does not match");
  const SamplingSettings settings = sampling_settings(c);

  SamplingPlan plan = plan_sampling(mesh, settings.step, settings.scheme);
  if (plan.lattice_sizes != c.get_counts("lattice_sizes", T)) {
    c.fail(
        "its lattice sizes are not those of its step: written by an ncverify that rounds "
        "differently; sample the mesh again");
  }
  const std::uint64_t total = predicted_sample_count(mesh, plan);
  if (total != c.count("/sampling/samples")) c.fail("the sample count does not match the lattice");
  const std::optional<Shard> shard = whole ? std::nullopt : settings.shard;
  const SampleRange range = shard ? shard_range(total, *shard) : SampleRange{0, total};
  check_memory_budget(fmt::format("{} ({} samples)", c.source(), range.size()),
                      static_cast<double>(range.size()) * kBytesPerSampleDownstream, false);
  SampleSet set = sample_mesh(std::move(mesh), std::move(plan), nullptr, shard);
  set.source = settings.source;
  set.step_spec = settings.step_spec;
  return set;
}

std::uint64_t write_samples_file(const SampleSet& set, OutputFile& out) {
  ContainerWriter writer(FileKind::samples, kSamplesFormatVersion, sample_set_meta(set));
  add_sample_sections(writer, set);
  return writer.write(out);
}

SamplingSettings read_sampling_settings(const std::string& path) {
  return sampling_settings(Container::read(path, FileKind::samples, kSamplesFormatVersion));
}

SampleSet read_samples_file(const std::string& path) {
  return load_sample_set(Container::read(path, FileKind::samples, kSamplesFormatVersion));
}

}  // namespace ncv
