#pragma once
// Large arrays written once from end to end (a million balls' scene, state and tracks) spend
// much of their time in page faults, one per 4 KiB on first write: on this project's virtual
// machines a fresh 400 MiB costs 1.3 s touched page by page and 0.6 s when the kernel maps it in
// one call beforehand. These ask for that call; where it is missing (other systems, older
// kernels) they do nothing and the pages fault in as before.

#include <cstddef>
#include <vector>

namespace carom {

// Maps the pages wholly inside [begin, begin + bytes) for writing, now.
void prefaultForWriting(void* begin, std::size_t bytes);

// Room for `count` elements, mapped in before they are written.
template <typename T>
void reservePrefaulted(std::vector<T>& values, std::size_t count) {
  values.reserve(count);
  if (count > values.size())
    prefaultForWriting(values.data() + values.size(), (count - values.size()) * sizeof(T));
}

// resize() to `count` default elements, mapped in first.
template <typename T>
void resizePrefaulted(std::vector<T>& values, std::size_t count) {
  reservePrefaulted(values, count);
  values.resize(count);
}

}  // namespace carom
