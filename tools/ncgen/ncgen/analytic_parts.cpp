#include "ncgen/analytic_parts.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace ncv::gen {
namespace {

struct ProfilePoint {
  double y = 0;
  double z = 0;
};

void add_quad(ncv::Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  mesh.triangles.push_back({a, b, c});
  mesh.triangles.push_back({a, c, d});
}

// The solid swept by the region between z = floor and a profile z(y) (y increasing) along x
// from x0 to x1: every face is a strip of quads, so any profile above the floor closes.
ncv::Mesh prism(double x0, double x1, const std::vector<ProfilePoint>& profile, double floor) {
  ncv::Mesh mesh;
  const auto vertex = [](std::size_t k, int corner) {
    return static_cast<std::uint32_t>(4 * k + static_cast<std::size_t>(corner));
  };
  enum { front_top, back_top, front_bottom, back_bottom };
  for (const ProfilePoint& p : profile) {
    mesh.vertices.push_back({x0, p.y, p.z});
    mesh.vertices.push_back({x1, p.y, p.z});
    mesh.vertices.push_back({x0, p.y, floor});
    mesh.vertices.push_back({x1, p.y, floor});
  }
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const std::size_t n = k + 1;
    add_quad(mesh, vertex(k, front_top), vertex(k, back_top), vertex(n, back_top),
             vertex(n, front_top));
    add_quad(mesh, vertex(k, front_bottom), vertex(n, front_bottom), vertex(n, back_bottom),
             vertex(k, back_bottom));
    add_quad(mesh, vertex(k, front_bottom), vertex(k, front_top), vertex(n, front_top),
             vertex(n, front_bottom));
    add_quad(mesh, vertex(k, back_bottom), vertex(n, back_bottom), vertex(n, back_top),
             vertex(k, back_top));
  }
  const std::size_t last = profile.size() - 1;
  add_quad(mesh, vertex(0, front_bottom), vertex(0, back_bottom), vertex(0, back_top),
           vertex(0, front_top));
  add_quad(mesh, vertex(last, front_bottom), vertex(last, front_top), vertex(last, back_top),
           vertex(last, back_bottom));
  return mesh;
}

// Breakpoints of the scallop profile: pass centres and cusps, then each half arc split evenly.
std::vector<double> scallop_stations(double length, double stepover, int segments) {
  std::vector<double> stations;
  const double half = stepover / 2;
  const int pieces = static_cast<int>(std::ceil(length / half - 1e-9));
  for (int piece = 0; piece < pieces; ++piece) {
    const double start = piece * half;
    const double end = std::min(start + half, length);
    for (int k = 0; k < segments; ++k) stations.push_back(start + (end - start) * k / segments);
  }
  stations.push_back(length);
  return stations;
}

}  // namespace

ncv::Mesh box_mesh(Vec3 min, Vec3 max) {
  return prism(min[0], max[0], {{min[1], max[2]}, {max[1], max[2]}}, min[2]);
}

double scallop_height(double radius, double stepover) {
  return radius - std::sqrt(radius * radius - stepover * stepover / 4);
}

ncv::Mesh scalloped_box(Vec3 size, double radius, double stepover, int segments) {
  if (!(stepover > 0 && stepover <= 2 * radius) || segments < 1) {
    throw std::invalid_argument("scallops need 0 < stepover <= 2 radius and segments >= 1");
  }
  std::vector<ProfilePoint> profile;
  for (double y : scallop_stations(size[1], stepover, segments)) {
    const double off_pass = std::abs(y - stepover * std::round(y / stepover));
    profile.push_back({y, size[2] + radius - std::sqrt(radius * radius - off_pass * off_pass)});
  }
  return prism(0, size[0], profile, 0);
}

ncv::Mesh grooved_box(Vec3 size, double centre_y, double width, double depth) {
  const double y0 = centre_y - width / 2, y1 = centre_y + width / 2;
  if (!(y0 > 0 && y1 < size[1] && depth < size[2] && width > 0)) {
    throw std::invalid_argument("the groove must lie inside the box top");
  }
  const double top = size[2], floor = top - depth;
  return prism(0, size[0],
               {{0, top}, {y0, top}, {y0, floor}, {y1, floor}, {y1, top}, {size[1], top}}, 0);
}

ncv::Mesh box_with_top_lines(Vec3 size, const std::vector<double>& lines_y) {
  std::vector<ProfilePoint> profile = {{0, size[2]}};
  for (double y : lines_y) profile.push_back({y, size[2]});
  profile.push_back({size[1], size[2]});
  return prism(0, size[0], profile, 0);
}

}  // namespace ncv::gen
