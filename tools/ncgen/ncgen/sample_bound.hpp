// A binary module for OpenMesh's decimater, our ModHausdorffT for height fields: a collapse is
// legal only if every sample removed so far under the faces it changes stays within
// `tolerance` (in 3D) of the face that then holds it seen from +z. Each removed sample is filed
// under that face, one on a height field, and measured again whenever a collapse changes it,
// so the bound holds for the final surface.
//
// Why not ModHausdorffT: it measures each sample against the ring's faces in turn, and after a
// collapse files every sample of the faces around v1 again by measuring all of them (the large
// finishing part took 40-41 s with it, 34 s with this, milling included); and those faces
// include ones the collapse did not change, whose other corners the decimater does not rate
// again, so a stale rating can miss a sample filed there. Here only the changed faces take
// samples, and all their corners are rated again. The holding face must be within the bound,
// not just any face of the ring: a sample passed by a neighbouring face would not be measured
// again when that face changes (a version that allowed it ended with samples 0.068 mm from a
// 0.05 mm bound on the small finishing part; the test that checks every sample caught it).
//
// Needs a top that stays a height field (HeightFieldGuardT, added before this module), so the
// faces around a vertex cover the same region before and after a collapse.
#pragma once

#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <array>
#include <vector>

#include "geometry/closest_point.hpp"

namespace ncv::gen {

template <class MeshT>
class SampleBoundT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(SampleBoundT, MeshT, SampleBound);

  using Point = typename MeshT::Point;
  using Corners = std::array<Point, 3>;

  explicit SampleBoundT(MeshT& mesh) : Base(mesh, true) { mesh.add_property(samples_); }
  ~SampleBoundT() override { Base::mesh().remove_property(samples_); }

  void set_tolerance(double tolerance) { squared_tolerance_ = tolerance * tolerance; }

  void initialize() override {
    for (const auto face : Base::mesh().faces()) Base::mesh().property(samples_, face).clear();
  }

  float collapse_priority(const CollapseInfo& ci) override {
    Mesh& mesh = Base::mesh();
    // The faces the collapse leaves around v0, with v0 at p1.
    faces_.clear();
    for (const auto h : mesh.voh_range(ci.v0)) {
      const auto face = mesh.face_handle(h);
      if (!face.is_valid() || face == ci.fl || face == ci.fr) continue;
      faces_.push_back({ci.p1, mesh.point(mesh.to_vertex_handle(h)),
                        mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)))});
    }
    if (!near_enough(ci.p0)) return static_cast<float>(Base::ILLEGAL_COLLAPSE);
    for (const auto face : mesh.vf_range(ci.v0)) {
      for (const Point& sample : mesh.property(samples_, face)) {
        if (!near_enough(sample)) return static_cast<float>(Base::ILLEGAL_COLLAPSE);
      }
    }
    return static_cast<float>(Base::LEGAL_COLLAPSE);
  }

  void preprocess_collapse(const CollapseInfo& ci) override {
    // v0's faces but the two the collapse removes keep their handles, with v1 for v0.
    handles_.clear();
    for (const auto face : Base::mesh().vf_range(ci.v0)) {
      if (face != ci.fl && face != ci.fr) handles_.push_back(face);
    }
  }

  void postprocess_collapse(const CollapseInfo& ci) override {
    Mesh& mesh = Base::mesh();
    // Those faces now cover what v0's faces covered: their samples, fl's, fr's and v0's are
    // filed again under the face of them that holds each. Only there: every corner of these
    // faces is a neighbour of v0 or v1, which the decimater rates again next, so no rating
    // misses a sample filed under one of its faces.
    pending_.clear();
    faces_.clear();
    const auto take = [&](typename Mesh::FaceHandle face) {
      std::vector<Point>& samples = mesh.property(samples_, face);
      pending_.insert(pending_.end(), samples.begin(), samples.end());
      samples.clear();
    };
    for (const auto face : handles_) {
      take(face);
      auto corner = mesh.cfv_iter(face);
      const Point& a = mesh.point(*corner);
      const Point& b = mesh.point(*++corner);
      const Point& c = mesh.point(*++corner);
      faces_.push_back({a, b, c});
    }
    if (ci.fl.is_valid()) take(ci.fl);
    if (ci.fr.is_valid()) take(ci.fr);
    pending_.push_back(ci.p0);
    for (const Point& sample : pending_) {
      mesh.property(samples_, handles_[holder(sample)]).push_back(sample);
    }
  }

 private:
  // The face of faces_ that holds the sample seen from +z (the first, on a shared edge), or
  // the nearest in 3D if none does (which on a height field cannot happen).
  std::size_t holder(const Point& sample) const {
    for (std::size_t k = 0; k < faces_.size(); ++k) {
      if (holds(faces_[k], sample)) return k;
    }
    std::size_t nearest = 0;
    double best = squared_distance(faces_[0], sample);
    for (std::size_t k = 1; k < faces_.size(); ++k) {
      const double d = squared_distance(faces_[k], sample);
      if (d < best) best = d, nearest = k;
    }
    return nearest;
  }

  bool near_enough(const Point& sample) const {
    return squared_distance(faces_[holder(sample)], sample) <= squared_tolerance_;
  }

  // Seen from +z, counter-clockwise faces: the sample on the inner side of all three edges.
  // Exact on grid samples (see height_field_guard.hpp).
  static bool holds(const Corners& c, const Point& p) {
    for (int k = 0; k < 3; ++k) {
      const Point& a = c[k];
      const Point& b = c[(k + 1) % 3];
      if ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) < 0) return false;
    }
    return true;
  }

  static double squared_distance(const Corners& c, const Point& p) {
    return closest_point_on_triangle(p, c[0], c[1], c[2]).squared_distance;
  }

  OpenMesh::FPropHandleT<std::vector<Point>> samples_;
  double squared_tolerance_ = 0;
  std::vector<Corners> faces_;
  std::vector<typename Mesh::FaceHandle> handles_;
  std::vector<Point> pending_;
};

}  // namespace ncv::gen
