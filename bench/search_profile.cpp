// Where the distance search spends its time, by how far samples lie from the nominal:
//   ncverify_search_profile WORKPIECE.stl NOMINAL.stl [STEP_FRACTION]
// samples the workpiece (scheme I, default δ = 0.1 % of its diagonal), searches every sample
// on one thread in order (as the distance step does, the hint dropped every block of 512)
// and prints, per class of distance to the nominal, the share of samples, the cells read,
// the cell-list entries box-checked and the exact tests per sample, and the wall time per
// sample (two clock reads included, some 40 ns).
// The same samples are also split by whether the hint was right: on or off the surface, and
// whether the closest triangle is the previous sample's (the hint) or another one.
// A second pass searches the samples again in the same order with each one's own closest
// triangle (from the first pass) as the hint: the cost with a perfect first guess, a floor
// for what a better hint could save.
// Last, whole passes timed at once (no clock per sample, whose cost would flatten ratios
// between nominals), both ways in alternation: the search-alone cost per sample, and its
// floor with a perfect hint.
// scripts/bench.sh runs it on the 17 k and the 1.7 M nominal: the classes show what the
// nominal's size changes.
#include <cmath>
#include <cstdio>
#include <vector>

#include "search/closest_point_search.hpp"
#include "search/search_index.hpp"
#include "util/stopwatch.hpp"
#include "workload.hpp"

namespace {

// Samples nearer the nominal than this (model units) are on its surface.
constexpr double kOnSurface = 1e-6;

struct SampleClass {
  const char* name;
  double below = INFINITY;  // upper bound of a distance class, model units
  std::size_t samples = 0;
  std::uint64_t tested = 0;
  std::uint64_t considered = 0;
  std::uint64_t cells = 0;
  double seconds = 0;

  void add(const ncv::SearchCounters& before, const ncv::SearchCounters& after, double time) {
    ++samples;
    tested += after.triangles_tested - before.triangles_tested;
    considered += after.triangles_considered - before.triangles_considered;
    cells += after.cells_visited - before.cells_visited;
    seconds += time;
  }
};

struct Profile {
  std::vector<SampleClass> by_distance;
  std::vector<SampleClass> by_hint;
};

std::vector<SampleClass> distance_classes() {
  return {{"on the surface (< 1e-6)", kOnSurface},
          {"< 0.01", 0.01},
          {"< 0.1", 0.1},
          {"< 0.3", 0.3},
          {">= 0.3", INFINITY}};
}

// Index: 2 * off the surface + closest triangle changed.
std::vector<SampleClass> hint_classes() {
  return {{"on, hint was closest"},
          {"on, closest changed"},
          {"off, hint was closest"},
          {"off, closest changed"}};
}

void print(const char* title, const std::vector<SampleClass>& classes, std::size_t total) {
  std::printf("%-26s%10s%8s%12s%8s%12s\n", title, "samples", "cells", "considered", "tested",
              "ns/sample");
  for (const SampleClass& c : classes) {
    if (c.samples == 0) continue;
    const auto n = static_cast<double>(c.samples);
    std::printf("%-26s%9.1f%%%8.2f%12.2f%8.2f%12.0f\n", c.name,
                100 * n / static_cast<double>(total), static_cast<double>(c.cells) / n,
                static_cast<double>(c.considered) / n, static_cast<double>(c.tested) / n,
                1e9 * c.seconds / n);
  }
}

// One pass over the points; `answers` receives each point's closest triangle or, when
// given one, supplies it as the hint.
Profile profile(ncv::GridSearcher& search, const std::vector<ncv::Vec3>& points,
                std::vector<std::uint32_t>& answers, bool answers_as_hints) {
  Profile result{distance_classes(), hint_classes()};
  ncv::SearchCounters counters;
  std::uint32_t previous = ncv::kNoTriangle;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (answers_as_hints) {
      search.set_hint(answers[i]);
    } else if (i % ncv::kDistanceBlockSize == 0) {
      search.forget_hint();
      previous = ncv::kNoTriangle;
    }
    const ncv::SearchCounters before = counters;
    const ncv::Stopwatch clock;
    const ncv::ClosestHit hit = search.closest(points[i], counters);
    const double seconds = clock.seconds();
    answers[i] = hit.triangle;
    const double distance = std::sqrt(hit.squared_distance);
    for (SampleClass& c : result.by_distance) {
      if (distance >= c.below) continue;
      c.add(before, counters, seconds);
      break;
    }
    const bool off = distance >= kOnSurface;
    const bool changed = hit.triangle != previous;
    result.by_hint[2 * off + changed].add(before, counters, seconds);
    previous = hit.triangle;
  }
  return result;
}

// One pass timed as a whole, in seconds per sample.
double whole_pass(ncv::GridSearcher& search, const std::vector<ncv::Vec3>& points,
                  const std::vector<std::uint32_t>& answers, bool answers_as_hints) {
  const ncv::Stopwatch clock;
  if (answers_as_hints) {
    ncv::SearchCounters counters;
    for (std::size_t i = 0; i < points.size(); ++i) {
      search.set_hint(answers[i]);
      search.closest(points[i], counters);
    }
  } else {
    ncv::bench::search_in_step_order(search, points, [](std::size_t, const ncv::ClosestHit&) {});
  }
  return clock.seconds() / static_cast<double>(points.size());
}

// The exact kernel alone on each sample's closest triangle, in seconds per sample: what any
// method that computes the exact distance pays at least once a sample, however it finds the
// triangle.
double kernel_floor(const ncv::ReferenceSurface& nominal, const std::vector<ncv::Vec3>& points,
                    const std::vector<std::uint32_t>& answers) {
  const ncv::MeshCorners corners = nominal.corners();
  const ncv::Stopwatch clock;
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    sum += ncv::closest_point_on_triangle(points[i], corners[answers[i]]).squared_distance;
  }
  const double seconds = clock.seconds();
  __asm__ volatile("" : : "g"(sum));  // the sum is used, so the loop is not optimised away
  return seconds / static_cast<double>(points.size());
}

}  // namespace

int main(int argc, char** argv) {
  ncv::bench::Workload w = ncv::bench::load_local_workload(argc, argv);
  const ncv::ReferenceSurface& nominal = *w.nominal.surface;
  const std::vector<ncv::Vec3>& points = w.points;

  const ncv::SearchIndex index(w.nominal);
  ncv::GridSearcher search(index);
  std::vector<std::uint32_t> answers(points.size());
  const Profile searched = profile(search, points, answers, false);
  const Profile hinted = profile(search, points, answers, true);
  std::printf("%zu samples, %zu nominal triangles, cell %.3f\n", points.size(),
              nominal.triangle_count(), w.nominal.grid.cell_size);
  print("distance class", searched.by_distance, points.size());
  print("surface, hint", searched.by_hint, points.size());
  std::printf("the same with each sample's closest triangle as the hint:\n");
  print("distance class", hinted.by_distance, points.size());
  print("surface, hint", hinted.by_hint, points.size());
  constexpr int kRounds = 5;
  std::vector<double> normal, perfect, floor;
  for (int round = 0; round < kRounds; ++round) {
    normal.push_back(whole_pass(search, points, answers, false));
    perfect.push_back(whole_pass(search, points, answers, true));
    floor.push_back(kernel_floor(nominal, points, answers));
  }
  std::printf(
      "whole passes, median of %d: %.1f ns/sample; with a perfect hint %.1f; the kernel alone on "
      "each sample's closest triangle %.1f\n",
      kRounds, 1e9 * ncv::bench::median(normal), 1e9 * ncv::bench::median(perfect),
      1e9 * ncv::bench::median(floor));
  return 0;
}
