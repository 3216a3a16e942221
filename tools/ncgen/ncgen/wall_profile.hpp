// Cross-section of a drafted wall rising from a lower plane to an upper one, with optional
// tangent fillets at its foot (concave) and head (convex), as a CAD part has them.
#pragma once

namespace ncv::gen {

struct WallProfile {
  double lower = 0.0;
  double upper = 1.0;
  double draft = 0.0;  // radians from vertical
  double foot_fillet = 0.0;
  double head_fillet = 0.0;  // 0: sharp edge

  // Height at inward distance u from the foot line, where the unfilleted wall meets the
  // lower plane (u < 0 is outside).
  double height(double u) const;
  // Where the upper plane starts (inward distance).
  double head_end() const;
};

}  // namespace ncv::gen
