#include "runners/distance_runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "files/grid_file.hpp"
#include "files/samples_file.hpp"
#include "sampling/measuring_order.hpp"
#include "sampling/sample_normals.hpp"
#include "search/search_index.hpp"
#include "util/error.hpp"
#include "util/memory_guard.hpp"
#include "util/progress.hpp"
#include "util/stopwatch.hpp"

namespace ncv {
namespace {

// Share of the smaller box's volume inside the other, with boxes grown by 1 % of the
// larger diagonal so flat parts still have a volume.
double overlap_share(const BoundingBox& a, const BoundingBox& b) {
  const double pad = 0.01 * std::max(a.diagonal(), b.diagonal());
  double inter = 1, va = 1, vb = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::max(a.min[axis], b.min[axis]) - pad;
    const double hi = std::min(a.max[axis], b.max[axis]) + pad;
    inter *= std::max(0.0, hi - lo);
    va *= a.max[axis] - a.min[axis] + 2 * pad;
    vb *= b.max[axis] - b.min[axis] + 2 * pad;
  }
  return inter / std::min(va, vb);
}

// Reverse: the error is + where the nominal point lies inside the workpiece (material left),
// the negated signed distance to the workpiece; a point on it stays +0.
void reverse_sign(Buffer<double>& distances) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, distances.size(), 1 << 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end(); ++i) {
                        distances[i] = distances[i] == 0 ? 0.0 : -distances[i];
                      }
                    });
}

// What a size ratio between the parts suggests: the usual unit factors by name.
std::string unit_mismatch(double ratio) {
  const double factor = ratio >= 1 ? ratio : 1 / ratio;
  const auto near = [factor](double unit) { return std::fabs(factor / unit - 1) < 0.05; };
  const std::string larger = ratio >= 1 ? "workpiece" : "nominal";
  if (near(25.4)) return "inches against millimetres? (the " + larger + " is the one in mm)";
  if (near(1000)) return "metres against millimetres? (the " + larger + " is the one in mm)";
  if (near(10)) return "centimetres against millimetres?";
  return "a unit mismatch?";
}

// A simulated workpiece is a dense mesh of small triangles and a CAD nominal a coarse one;
// the other way round by far, the two were probably given in the wrong order.
void warn_if_swapped(const Mesh& workpiece, const std::string& workpiece_source,
                     const Mesh& nominal, const std::string& nominal_source) {
  const auto w = static_cast<double>(workpiece.triangle_count());
  const auto n = static_cast<double>(nominal.triangle_count());
  if (!(n > 20 * w) || w == 0) return;
  const double workpiece_mean = surface_area(workpiece) / w,
               nominal_mean = surface_area(nominal) / n;
  if (workpiece_mean > 20 * nominal_mean) {
    spdlog::warn(
        "the workpiece ({}, {} triangles) is far coarser than the nominal ({}, {} triangles): "
        "were they given the other way round? (the workpiece comes first)",
        workpiece_source, workpiece.triangle_count(), nominal_source, nominal.triangle_count());
  }
}

void log_certificate(const Certificate& c, Direction direction, double seconds) {
  spdlog::info(
      "{}: certified between samples in {:.3f} s: max in [{:.6g}, {:.6g}], min in [{:.6g}, "
      "{:.6g}]; {} sub-triangles bounded, {} split, {} points added{}",
      name_of(kDirectionNames, direction), seconds, c.max.measured, c.max.bound, c.min.bound,
      c.min.measured, c.patches, c.refined_patches, c.added_points,
      c.unresolved ? fmt::format(", {} still wider than {:.3g} (refinement cap)", c.unresolved,
                                 c.width_asked)
                   : "");
}

}  // namespace

void refuse_if_apart(const BoundingBox& workpiece, const std::string& workpiece_source,
                     const BoundingBox& nominal, const std::string& nominal_source) {
  const double gap = box_gap(workpiece, nominal);
  const double size = std::max(workpiece.diagonal(), nominal.diagonal());
  if (gap > size) {
    throw InputError(workpiece_source,
                     fmt::format("the workpiece lies {:.6g} from the nominal {}, farther than "
                                 "the size of either part ({:.6g}): they do not belong together "
                                 "(a wrong file or coordinate frame?)",
                                 gap, nominal_source, size));
  }
}

// What the two files' geometry can tell about whether they belong together. Certain: a
// workpiece whose every point is farther from the nominal than the size of either part is
// not a machining of it in its frame; no tolerance verdict on it means anything, and an
// "out of tolerance" would send someone to rework a part that was never measured, so it is
// refused. Only suspicious (warned, measured anyway): little overlap, no overlap at close
// range, very different sizes, or the nominal itself given as the workpiece (zero
// everywhere; a legitimate self-check, a mix-up otherwise).
void check_parts(const Mesh& workpiece, const std::string& workpiece_source, const Mesh& nominal,
                 const std::string& nominal_source) {
  const BoundingBox workpiece_box = bounding_box(workpiece), nominal_box = bounding_box(nominal);
  refuse_if_apart(workpiece_box, workpiece_source, nominal_box, nominal_source);
  if (workpiece.triangle_count() == nominal.triangle_count() &&
      mesh_hash(workpiece) == mesh_hash(nominal)) {
    spdlog::warn("the workpiece ({}) is the nominal ({}) itself: every distance is zero",
                 workpiece_source, nominal_source);
  }
  const double share = overlap_share(workpiece_box, nominal_box);
  if (share < 0.5) {
    spdlog::warn(
        "the workpiece ({}) and the nominal ({}) barely overlap ({:.0f} % of the "
        "smaller bounding box): a wrong file, unit or coordinate frame?",
        workpiece_source, nominal_source, 100 * share);
  }
  const double ratio = workpiece_box.diagonal() / std::max(nominal_box.diagonal(), 1e-300);
  if (ratio > 5 || ratio < 0.2) {
    spdlog::warn("the workpiece is {:.3g} times the size of the nominal: {}", ratio,
                 unit_mismatch(ratio));
  }
  warn_if_swapped(workpiece, workpiece_source, nominal, nominal_source);
}

DistanceSet measure_distances(SampleSet samples, const SearchIndex& index,
                              const DistanceOptions& options, double* seconds) {
  const IndexedReference& reference = index.reference();
  if (options.direction == Direction::forward) {
    refuse_if_apart(bounding_box(samples.mesh), samples.source, bounding_box(*reference.mesh),
                    reference.source);
  } else {
    refuse_if_apart(bounding_box(*reference.mesh), reference.source, bounding_box(samples.mesh),
                    samples.source);
  }
  if (options.certify) {
    const std::uint64_t cap = certify_points_cap(*options.certify, samples.total_samples);
    check_memory_budget(fmt::format("certifying with up to {} added points", cap),
                        static_cast<double>(cap) * kBytesPerCertifyPoint, false,
                        "give a smaller --certify-points");
  }
  const ReferenceSurface& surface = *reference.surface;
  const SignMethod method = resolve_sign_method(surface, options.sign);
  const std::vector<Vec3> normals =
      method == SignMethod::paper ? sample_normals(samples) : std::vector<Vec3>{};

  Stopwatch clock;
  SearchStatistics statistics;
  Progress progress("distance", samples.sample_count());
  const auto report = [&](std::size_t done, std::size_t) { progress.update(done); };
  DistanceSet result;
  const SideRule side(surface, method);
  if (options.brute_force) {
    result.field =
        compute_signed_distances(surface, samples.positions, normals, side, &statistics, report);
  } else {
    const Buffer<std::uint32_t> order = measuring_order(samples);
    result.field = compute_signed_distances(index, samples.positions, normals, side, &statistics,
                                            report, order);
  }
  progress.finish();
  const auto per_query = [&](std::uint64_t count) {
    return static_cast<double>(count) /
           static_cast<double>(std::max<std::uint64_t>(statistics.queries, 1));
  };
  spdlog::debug(
      "search: {} queries; per query {:.2f} cells visited, {:.2f} triangles box-checked "
      "(hints included), {:.2f} tested exactly; sign by {} ({})",
      statistics.queries, per_query(statistics.cells_visited),
      per_query(statistics.triangles_considered), per_query(statistics.triangles_tested),
      name_of(kSignMethodNames, method),
      options.sign == SignMethod::automatic ? "chosen by --sign auto" : "as asked");
  if (seconds) *seconds = clock.seconds();
  if (options.certify) {
    Stopwatch certify_clock;
    const Certificate raw = certify_surface(samples, result.field, index, side, *options.certify);
    result.certificate = options.direction == Direction::reverse ? negated(raw) : raw;
    log_certificate(*result.certificate, options.direction, certify_clock.seconds());
  }
  if (options.direction == Direction::reverse) reverse_sign(result.field.distance);

  result.direction = options.direction;
  result.samples = std::move(samples);
  result.reference = {reference.source, reference.hash, reference.mesh->triangle_count(),
                      bounding_box(*reference.mesh)};
  result.sign_method = std::string(name_of(kSignMethodNames, method));
  result.search = options.brute_force ? "brute-force" : "grid";
  result.triangles_tested = statistics.triangles_tested;
  return result;
}

void log_distances(const DistanceSet& d, double seconds) {
  const auto samples = static_cast<double>(d.samples.sample_count());
  spdlog::info(
      "{}: {} samples of {} against {} triangles of {} in {:.3f} s ({:.3g} samples/s); {} "
      "search, {:.1f} triangles tested per sample; sign by {}",
      name_of(kDirectionNames, d.direction), d.samples.sample_count(), d.samples.source,
      d.reference.triangles, d.reference.source, seconds, samples / std::max(seconds, 1e-9),
      d.search, d.triangles_tested_per_sample(), d.sign_method);
}

// Output opened first and the report after the commit, as in `sample`.
void run_distance(const DistanceJob& job) {
  OutputFile out(job.output, OutputKind::binary);
  const Container samples_file =
      Container::read(job.samples, FileKind::samples, kSamplesFormatVersion);
  SampleSet samples = load_sample_set(samples_file);
  const IndexedReference reference = read_grid_file(job.grid);
  if (job.options.direction == Direction::forward) {
    check_parts(samples.mesh, samples.source, *reference.mesh, reference.source);
  } else {
    check_parts(*reference.mesh, reference.source, samples.mesh, samples.source);
  }
  const SearchIndex index(reference);
  double seconds = 0;
  const DistanceSet result = measure_distances(std::move(samples), index, job.options, &seconds);
  write_distance_file(result, link_samples(job.samples, samples_file.content_hash(), job.output),
                      out);
  out.commit();
  log_distances(result, seconds);
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace ncv
