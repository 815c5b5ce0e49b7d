// Per-pixel work spread over the CPUs this process may use (boxCores, read once a process):
// the rows (or columns) are cut into contiguous bands, one thread each. Only for work whose
// result cannot depend on which thread does a row: each band writes its own pixels and its own
// accumulators, and the caller combines the bands in order.
#pragma once

#include <functional>

namespace sl {

// How many bands `count` rows of `costPerRow` pixels each are worth: one per usable core, but
// never bands under about 16k pixels (a thread's start costs more than they take).
int rowBandCount(int count, long costPerRow);

// Runs body(band, first, end) for `bands` contiguous bands covering [0, count) in order (band
// b's rows come before band b + 1's), each band on its own thread, the first on the caller's.
// An exception in any band is rethrown here once all have finished.
void forRowBands(int count, int bands,
                 const std::function<void(int band, int first, int end)>& body);

}  // namespace sl
