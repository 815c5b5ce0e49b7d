#include "metrics/row_bands.h"

#include <algorithm>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

#include "io/box.h"

namespace sl {

int rowBandCount(int count, long costPerRow) {
    constexpr long kLeastPixelsPerBand = 16384;
    if (count <= 0) return 1;
    long worth = std::max(1L, long(count) * std::max(1L, costPerRow) / kLeastPixelsPerBand);
    return int(std::clamp<long>(worth, 1, std::min(boxCores(), count)));
}

void forRowBands(int count, int bands,
                 const std::function<void(int band, int first, int end)>& body) {
    bands = std::clamp(bands, 1, std::max(1, count));
    auto first = [&](int b) { return int(long(count) * b / bands); };
    if (bands == 1) {
        body(0, 0, count);
        return;
    }
    std::vector<std::exception_ptr> failed(bands);
    auto run = [&](int b) {
        try {
            body(b, first(b), first(b + 1));
        } catch (...) {
            failed[b] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(bands - 1);
    int started = 1;
    try {
        for (; started < bands; ++started) threads.emplace_back(run, started);
    } catch (const std::system_error&) {  // no more threads to be had: the rest run here
    }
    for (int b = started; b < bands; ++b) run(b);
    run(0);
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);
}

}  // namespace sl
