// The verdict of a direction against a tolerance zone (docs/REPORTS.md "Verdict"):
//   fail          a measured point (a sample, or a point certification added) lies outside
//                 the zone: the part is out of tolerance there, for certain;
//   pass          the certified bounds on the largest and smallest error over the whole
//                 sampled surface lie inside the zone, and every triangle was sampled;
//   inconclusive  neither: between the samples the error may leave the zone, or nothing
//                 bounds it there (no certificate, or triangles left unsampled by scheme II).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "certify/certificate.hpp"
#include "statistics/error_statistics.hpp"
#include "statistics/readable_numbers.hpp"
#include "util/enum_names.hpp"

namespace ncv {

enum class Verdict : std::uint8_t { pass, fail, inconclusive };

inline constexpr EnumName<Verdict> kVerdictNames[] = {
    {Verdict::pass, "pass"}, {Verdict::fail, "fail"}, {Verdict::inconclusive, "inconclusive"}};

Verdict judge(const ErrorStatistics& statistics, const std::optional<Certificate>& certificate,
              const Tolerance& tolerance);

// The worse of two verdicts: fail over inconclusive over pass.
Verdict worse(Verdict a, Verdict b);

// Why, in a sentence a machinist reads: what was measured outside the zone, or where the
// error may leave it between the samples and by how much, or what is missing for a proof.
std::string verdict_reason(const ErrorStatistics& statistics,
                           const std::optional<Certificate>& certificate,
                           const Tolerance& tolerance, const NumberStyle& numbers);

}  // namespace ncv
