// Shared by load_groups.cpp (finding the groups) and load_group_edits.cpp (changing them); not
// part of the session's interface.
#pragma once

#include <string>
#include <vector>

#include "session/input_checks.hpp"
#include "session/load_groups.hpp"

namespace styk::gui::detail {

// Group `entry.item` of `groups`, or InputError.
template <typename Group>
const Group& group_at(const std::vector<Group>& groups, const Entry& entry) {
  if (entry.item < 0 || entry.item >= static_cast<int>(groups.size()))
    refuse("the list has no entry " + std::to_string(entry.item + 1));
  return groups[entry.item];
}

// How a group's nodes are named: the set chosen in the dialog, the set they form, or "N nodes".
std::string nodes_name(const std::string& nset, const NodeGroup& group);

}  // namespace styk::gui::detail
