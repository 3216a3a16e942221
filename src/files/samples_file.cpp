#include "files/samples_file.hpp"

#include <fmt/format.h>

#include <cmath>

#include "files/mesh_arrays.hpp"

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

// Vertex samples are 0..k-1 in vertex order, exactly the vertices of sampled triangles.
std::uint64_t validate_vertex_samples(const SampleSet& set, const Container& from) {
  std::vector<bool> needed(set.mesh.vertex_count(), false);
  for (std::size_t t = 0; t < set.lattice_sizes.size(); ++t) {
    if (set.lattice_sizes[t] == 1) from.fail("a triangle has lattice size 1");
    if (set.lattice_sizes[t] == 0) continue;
    for (std::uint32_t v : set.mesh.triangles[t]) needed[v] = true;
  }
  std::uint64_t next = 0;
  for (std::size_t v = 0; v < needed.size(); ++v) {
    const std::uint32_t expected = needed[v] ? static_cast<std::uint32_t>(next++) : kNoSample;
    if (set.vertex_sample[v] != expected) from.fail("vertex sample numbering is inconsistent");
  }
  return next;
}

void validate_lattice(const SampleSet& set, const Container& from) {
  std::uint64_t next = validate_vertex_samples(set, from);
  const std::uint64_t samples = set.sample_count();
  for (std::size_t t = 0; t < set.lattice_sizes.size(); ++t) {
    const std::uint64_t own = lattice_interior_count(set.lattice_sizes[t]);
    if (set.first_interior_sample[t] != next || own > samples - std::min(samples, next)) {
      from.fail("per-triangle sample offsets are inconsistent");
    }
    next += own;
  }
  if (next != samples) from.fail("sample count does not match the lattice");
  for (std::uint64_t s = 0; s < samples; ++s) {
    const std::uint32_t t = set.owner[s];
    if (t >= set.lattice_sizes.size() || set.lattice_sizes[t] < 2)
      from.fail("a sample has an invalid owner");
    const std::uint64_t n = set.lattice_sizes[t];
    const std::uint64_t i = set.lattice_i[s], j = set.lattice_j[s];
    if (i + j > n - 1 || set.sample_at(t, set.lattice_i[s], set.lattice_j[s]) != s) {
      from.fail("a sample's lattice coordinates are inconsistent");
    }
    if (!is_finite(set.positions[s])) from.fail("a sample position is not finite");
  }
}

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
  return settings;
}

}  // namespace

nlohmann::json sample_set_meta(const SampleSet& set) {
  const BoundingBox box = bounding_box(set.mesh);
  return {{"tool", "ncverify " NCV_VERSION},
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
            {"samples", set.sample_count()}}},
          {"records",
           {{"name", "samples"},
            {"count", set.sample_count()},
            {"sections", {"positions", "owner", "lattice_i", "lattice_j"}}}}};
}

void add_sample_sections(ContainerWriter& writer, const SampleSet& set) {
  const std::uint64_t V = set.mesh.vertex_count(), T = set.mesh.triangle_count(),
                      S = set.sample_count();
  writer.add<double>("mesh_vertices", flat_coordinates(set.mesh.vertices), {V, 3});
  writer.add<std::uint32_t>("mesh_triangles", flat_indices(set.mesh.triangles), {T, 3});
  writer.add<std::uint32_t>("tri_n", set.lattice_sizes, {T});
  writer.add<std::uint64_t>("tri_first", set.first_interior_sample, {T});
  writer.add<std::uint32_t>("vertex_sample", set.vertex_sample, {V});
  writer.add<double>("positions", flat_coordinates(set.positions), {S, 3});
  writer.add<std::uint32_t>("owner", set.owner, {S});
  writer.add<std::uint32_t>("lattice_i", set.lattice_i, {S});
  writer.add<std::uint32_t>("lattice_j", set.lattice_j, {S});
}

SampleSet load_sample_set(const Container& c) {
  SampleSet set;
  const std::uint64_t V = c.count("/mesh/vertices"), T = c.count("/mesh/triangles"),
                      S = c.count("/sampling/samples");
  set.mesh.vertices = c.get_rows<double, Vec3>("mesh_vertices", V);
  set.mesh.triangles = c.get_rows<std::uint32_t, Triangle>("mesh_triangles", T);
  validate_mesh(set.mesh, c);
  if (!c.field("/mesh/hash").is_string()) c.fail("mesh hash is malformed");
  set.mesh_hash = parse_hash_hex(c.field("/mesh/hash").get<std::string>(), c);
  if (mesh_hash(set.mesh) != set.mesh_hash) c.fail("mesh hash does not match");
  const SamplingSettings settings = sampling_settings(c);
  set.source = settings.source;
  set.step = settings.step;
  set.step_spec = settings.step_spec;
  set.scheme = settings.scheme;
  set.lattice_sizes = c.get<std::uint32_t>("tri_n", T);
  set.first_interior_sample = c.get<std::uint64_t>("tri_first", T);
  set.vertex_sample = c.get<std::uint32_t>("vertex_sample", V);
  set.positions = c.get_rows<double, Vec3>("positions", S);
  set.owner = c.get<std::uint32_t>("owner", S);
  set.lattice_i = c.get<std::uint32_t>("lattice_i", S);
  set.lattice_j = c.get<std::uint32_t>("lattice_j", S);
  validate_lattice(set, c);
  return set;
}

void write_samples_file(const SampleSet& set, OutputFile& out) {
  ContainerWriter writer(FileKind::samples, kSamplesFormatVersion, sample_set_meta(set));
  add_sample_sections(writer, set);
  writer.write(out);
}

SamplingSettings read_sampling_settings(const std::string& path) {
  return sampling_settings(Container::read(path, FileKind::samples, kSamplesFormatVersion));
}

SampleSet read_samples_file(const std::string& path) {
  return load_sample_set(Container::read(path, FileKind::samples, kSamplesFormatVersion));
}

}  // namespace ncv
