#pragma once
// A vector's buffer as JS reads it (its address in the wasm heap), and its memory given back.
#include <cstdint>
#include <vector>

namespace geocdt::wasm {

template <typename T>
std::uintptr_t heapAddress(const std::vector<T>& v) {
  return reinterpret_cast<std::uintptr_t>(v.data());
}

// clear() keeps the capacity; a swap with an empty vector frees it.
template <typename T>
void freeVector(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

}  // namespace geocdt::wasm
