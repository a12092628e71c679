// The subcommand registry of commands.h, filled by the command files during static
// initialisation and read by main.
#include <algorithm>
#include <utility>
#include <vector>

#include "commands.h"

namespace gloss {

namespace {

// Constructed on first use, so registrations from any translation unit's initialisers are safe.
std::vector<std::pair<int, AddCommand>>& command_registry() {
  static std::vector<std::pair<int, AddCommand>> registry;
  return registry;
}

}  // namespace

bool register_command(int order, AddCommand add) {
  command_registry().emplace_back(order, add);
  return true;
}

std::vector<AddCommand> registered_commands() {
  std::vector<std::pair<int, AddCommand>> sorted = command_registry();
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<AddCommand> out;
  for (const auto& item : sorted) out.push_back(item.second);
  return out;
}

}  // namespace gloss
