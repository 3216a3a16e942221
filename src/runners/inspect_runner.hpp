// `ncverify inspect FILE`: the header and records of any ncverify file, as text, JSON or CSV
// (docs/FORMATS.md).
#pragma once

#include <cstdint>
#include <string>

namespace ncv {

struct InspectJob {
  std::string file;
  std::string output = "-";
  bool json = false;       // the header and metadata as JSON
  bool csv = false;        // the records as CSV
  std::int64_t head = -1;  // only the first N records; -1 = all
};
void run_inspect(const InspectJob& job);

}  // namespace ncv
