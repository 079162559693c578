#pragma once
// What a container holds on the heap, for the recording's memory bound (Simulation::memoryBytes).

#include <cstddef>
#include <vector>

namespace carom {

template <typename T>
std::size_t memoryBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

}  // namespace carom
