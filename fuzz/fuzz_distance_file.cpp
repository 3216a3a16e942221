// Distance files (kind DIST) as `stats` and `colorize` read them: Container::parse,
// load_distance_records, the samples the file holds (the corpus's files were made from
// standard input, so they embed them; a linked samples file is not found and refused), then the
// report (statistics, histogram, regions, text, JSON and CSV) and the coloured PLY of both the
// workpiece and the lattice, which trust what the loader accepted.
#include <sstream>

#include "files/container.hpp"
#include "files/distance_file.hpp"
#include "fuzz_support.hpp"
#include "render/color_map.hpp"
#include "render/error_mesh.hpp"
#include "render/ply_writer.hpp"
#include "statistics/statistics_report.hpp"
#include "util/output_file.hpp"

namespace {

void read_distances(ncv::Buffer<char> bytes) {
  ncv::Container c = ncv::Container::parse(std::move(bytes), "fuzz.dist", ncv::FileKind::distances,
                                           ncv::kDistancesFormatVersion);
  ncv::DistanceRecords records = ncv::load_distance_records(std::move(c), "fuzz.dist");
  ncv::SampleSet samples = ncv::load_linked_samples(records, "", false);
  const ncv::DistanceSet set = ncv::assemble_distance_set(std::move(records), std::move(samples));
  const ncv::Tolerance tolerance{-0.05, 0.1};
  const ncv::VerificationReport report{
      ncv::make_part_report(set, tolerance, ncv::HistogramOptions{}), std::nullopt};
  std::ostringstream out;
  out << ncv::report_text(report) << ncv::report_json(report).dump() << ncv::report_csv_row(report);
  const ncv::ColorMap map = ncv::make_color_map(ncv::ColorMapKind::tolerance, {-1, 1}, tolerance);
  ncv::OutputFile ply("/dev/null", ncv::OutputKind::binary);
  const ncv::ErrorMesh coarse = ncv::workpiece_error_mesh(set.samples, set.field.distance);
  ncv::write_error_ply(ply, ncv::ErrorMeshPly(coarse), map);
  ncv::write_error_ply(ply, ncv::LatticeMesh(set.samples, set.field.distance), map);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  ncv::fuzz::accepts([&] { read_distances(ncv::Buffer<char>(data, data + size)); });
  ncv::fuzz::accepts([&] { read_distances(ncv::fuzz::sealed_container(data, size)); });
  return 0;
}
