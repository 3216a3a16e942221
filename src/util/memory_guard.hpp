// Refuses work whose memory would not fit the machine, before allocating it.
#pragma once

#include <cstdint>
#include <string>

namespace ncv {

std::uint64_t physical_memory_bytes();
// Peak resident memory of this process so far.
std::uint64_t peak_memory_bytes();
std::string format_bytes(std::uint64_t bytes);  // "1.5 GB"

// What a step may plan to use: half the physical memory, at most 80 % of a Slurm job's
// --mem (SLURM_MEM_PER_NODE), and at most NCV_MEMORY_BUDGET bytes when that is set.
std::uint64_t memory_budget_bytes();

// Throws UsageError (what it would take, how much memory, the way out) when `bytes`
// exceeds the memory budget, unless forced.
void check_memory_budget(const std::string& what, double bytes, bool force,
                         const std::string& way_out = "use a larger step, or --force");

}  // namespace ncv
