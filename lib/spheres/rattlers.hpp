#pragma once
// Rattlers: spheres that carry no load in a jammed packing. The standard iterative rule (the
// thesis, 5.5.1, rejects packings with rattlers but does not define them): remove every sphere
// with fewer than d + 1 = 4 contacts, which may strip its partners below 4 in turn, until none
// is left (the removal is packing::prune_rattlers; this file is the spheres' rule).
#include "spheres/hertz_spheres.hpp"

#include <vector>

namespace cmp::spheres {

// Per sphere: true when it is a rattler. n: number of spheres; contacts: touching pairs.
std::vector<bool> find_rattlers(int n, const std::vector<Contact>& contacts, int min_contacts = 4);

// Contacts of every sphere (how many pairs it belongs to).
std::vector<int> contact_counts(int n, const std::vector<Contact>& contacts);

}  // namespace cmp::spheres
