#pragma once
// --threads N handling: 0 (the default) means every core the process may use.

namespace fest {

// Cores available to this process (affinity mask, cgroup-agnostic), at least 1.
int available_cores();

// Validates a --threads value: 0 -> available_cores(); negative -> usage error;
// values above 4x the cores are allowed (oversubscription is the user's choice).
int resolve_threads(int requested);

}  // namespace fest
