#pragma once
// Worker-thread counts: 0 (the default) means every core the process may use.

namespace fest {

// Cores available to this process (affinity mask, cgroup-agnostic), at least 1.
int available_cores();

// The largest thread count taken as meant (more is a typing error, not a machine).
constexpr int max_plausible_threads = 4096;

// Validates a requested thread count: 0 -> available_cores(); negative or above
// max_plausible_threads -> usage error; values above the cores are allowed
// (oversubscription is the user's choice).
int resolve_threads(int requested);

}  // namespace fest
