#include "base/memory_budget.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>

namespace gloss {

namespace {

constexpr std::uint64_t kMegabyte = 1024 * 1024;

// The variable's value in MB, or 0 when it is unset or not a whole number >= 1.
std::uint64_t budget_from_environment() {
  const char* text = std::getenv(kMemoryBudgetVariable);
  if (text == nullptr || *text == '\0') return 0;
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0' || text[0] == '-' || value == 0) return 0;
  // Past 2^44 MB (16 EB) the byte count would overflow: no machine has that much anyway.
  return value > (1ULL << 44) ? (1ULL << 44) : value;
}

std::uint64_t half_physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return 4096 * kMegabyte;  // unknown: a modest 4 GB
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size) / 2;
}

}  // namespace

std::uint64_t memory_budget_bytes() {
  const std::uint64_t mb = budget_from_environment();
  return mb > 0 ? mb * kMegabyte : half_physical_memory();
}

std::string memory_budget_text() {
  const std::string mb = std::to_string(megabytes(memory_budget_bytes())) + " MB";
  if (budget_from_environment() > 0) return mb + " (" + kMemoryBudgetVariable + ")";
  return mb + " (half of the physical memory; " + kMemoryBudgetVariable + " sets it)";
}

std::uint64_t megabytes(std::uint64_t bytes) {
  return (bytes + kMegabyte - 1) / kMegabyte;
}

}  // namespace gloss
