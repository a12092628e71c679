#pragma once
// How much memory one scene may claim (docs/spec/scene-and-cli.md, "Memory budget"): work whose
// estimate exceeds it is refused before anything is allocated, naming the object or setting.
#include <cstdint>
#include <string>

namespace gloss {

// The environment variable that sets the budget in MB (a whole number >= 1).
inline const char* const kMemoryBudgetVariable = "GLOSS_MEMORY_BUDGET_MB";

// The budget in bytes: GLOSS_MEMORY_BUDGET_MB when set to a whole number >= 1, else half the
// machine's physical memory (the other half for the system, the editor's GPU driver and
// estimates that run short). Read from the environment at each call.
std::uint64_t memory_budget_bytes();

// "N MB (GLOSS_MEMORY_BUDGET_MB)" or "N MB (half of the physical memory; GLOSS_MEMORY_BUDGET_MB
// sets it)", for messages.
std::string memory_budget_text();

// Bytes in whole MB (2^20), rounded up, for messages.
std::uint64_t megabytes(std::uint64_t bytes);

}  // namespace gloss
