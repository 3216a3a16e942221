// The date a report is stamped with.
#pragma once

#include <string>

namespace ncv {

// Now as ISO 8601 UTC ("2026-11-24T17:20:29Z"), or the time in SOURCE_DATE_EPOCH (seconds
// since 1970) when that is set, the reproducible-builds convention, so that two runs on the
// same inputs can give byte-identical reports.
std::string report_timestamp();

}  // namespace ncv
