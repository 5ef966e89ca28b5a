#pragma once
// Heap use of the whole benchmark process, counted by replacing the global operator new
// and delete (heap_counter.cpp). Both geocdt and CGAL allocate through them, so the peak
// between resetHeapPeak() and heapPeak() is the peak extra heap of the code run in between.
#include <cstddef>

namespace bench {

std::size_t heapInUse();
std::size_t heapPeak();
void resetHeapPeak();  // the peak restarts from the current use

}  // namespace bench
