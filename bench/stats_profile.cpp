// Where run's stats phase spends its time, on distance files already measured:
//   ncverify_stats_profile DIST [DIST] --tol LOWER:UPPER [--threads N] [--reps R]
// reads the part's distance files once, then times each piece of the stats phase R times
// (default 7) and prints the median of each in milliseconds: the error statistics
// (moments, tolerance areas, histogram, percentiles: compute_error_statistics), the
// out-of-tolerance regions (map_error_regions) and the reports' text (text, JSON, CSV,
// regions CSV, histogram CSV and SVG), per direction, and their sum.
#include <malloc.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "files/distance_job.hpp"
#include "runners/report_runner.hpp"
#include "statistics/error_regions.hpp"
#include "statistics/error_statistics.hpp"
#include "util/stopwatch.hpp"

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

template <class Work>
double median_ms(int reps, Work&& work) {
  std::vector<double> times;
  for (int r = 0; r < reps; ++r) {
    ncv::Stopwatch clock;
    work();
    times.push_back(1e3 * clock.seconds());
  }
  return median(times);
}

void profile(const char* name, const ncv::DistanceSet& set, const ncv::ReportOptions& options,
             int reps) {
  const auto& d = set.field.distance;
  const double statistics = median_ms(reps, [&] {
    (void)ncv::compute_error_statistics(set.samples, d, options.tolerance, options.histogram);
  });
  const double regions = median_ms(reps, [&] {
    if (options.tolerance) (void)ncv::map_error_regions(set.samples, d, *options.tolerance);
  });
  ncv::VerificationReport report{ncv::make_report(set, options), std::nullopt, {}};
  const double text = median_ms(reps, [&] {
    (void)ncv::format_report(report, ncv::ReportFormat::text);
    (void)ncv::format_report(report, ncv::ReportFormat::json);
    (void)ncv::format_report(report, ncv::ReportFormat::csv);
    (void)ncv::regions_csv(report.main);
    (void)ncv::histogram_csv(report.main);
    (void)ncv::histogram_svg(report.main);
  });
  std::printf("%-8s %10zu samples  statistics %7.1f  regions %7.1f  reports %6.1f  sum %7.1f ms\n",
              name, d.size(), statistics, regions, text, statistics + regions + text);
}

}  // namespace

int main(int argc, char** argv) {
  // glibc's limits as ncverify sets them (cmd/main.cpp): with glibc's defaults the brackets'
  // growing arrays were mapped fresh every time, and the timings depended on what ran before.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  std::vector<std::string> files;
  ncv::ReportOptions options;
  int threads = 0, reps = 7;
  for (int k = 1; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (arg == "--tol" && k + 1 < argc) {
      options.tolerance = ncv::parse_tolerance(argv[++k]);
    } else if (arg == "--threads" && k + 1 < argc) {
      threads = std::atoi(argv[++k]);
    } else if (arg == "--reps" && k + 1 < argc) {
      reps = std::max(1, std::atoi(argv[++k]));
    } else {
      files.emplace_back(arg);
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s DIST [DIST] --tol LOWER:UPPER [--threads N] [--reps R]\n",
                 argv[0]);
    return 2;
  }
  const auto limit = static_cast<std::size_t>(
      threads > 0
          ? threads
          : tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, limit);
  const ncv::PartDistances part = ncv::read_part_distances(files);
  profile("forward", part.main, options, reps);
  if (part.reverse) profile("reverse", *part.reverse, options, reps);
  return 0;
}
