#include "transport/uniform/form_factors_rows.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

namespace rad {

namespace {

// Rows per wave: enough to keep every core busy between the waves' short sequential compaction steps.
constexpr std::size_t kWaveRows = 2048;

// One wave's rows, compacted: row lengths, then all their columns and values back to back.
struct WaveBlock {
    std::vector<std::uint64_t> lengths;
    std::vector<std::uint32_t> columns;
    std::vector<float> values;
};

struct RowResult {
    std::vector<RowEntry> entries;
    RowStats stats;
};

WaveBlock compact(std::vector<RowResult>& wave, RowStats& stats) {
    WaveBlock block;
    std::size_t total = 0;
    for (const RowResult& r : wave) total += r.entries.size();
    block.lengths.reserve(wave.size());
    block.columns.reserve(total);
    block.values.reserve(total);
    for (RowResult& r : wave) {
        block.lengths.push_back(r.entries.size());
        for (const RowEntry& e : r.entries) {
            block.columns.push_back(e.column);
            block.values.push_back(static_cast<float>(e.value));
        }
        stats += r.stats;
        r.entries.clear();  // keeps its capacity for the next wave
        r.stats = RowStats{};
    }
    return block;
}

// Moves the blocks into one matrix. Columns go first and values second, each block freed as it is copied,
// so at no time are more than the matrix and half of it again in memory.
FormFactorMatrix concatenate(std::vector<WaveBlock>& blocks) {
    FormFactorMatrix matrix;
    std::size_t rows = 0;
    for (const WaveBlock& b : blocks) rows += b.lengths.size();
    matrix.row_begin.reserve(rows + 1);
    for (const WaveBlock& b : blocks) {
        for (std::uint64_t length : b.lengths) matrix.row_begin.push_back(matrix.row_begin.back() + length);
    }
    const std::size_t nonzeros = matrix.row_begin.back();
    matrix.column.reserve(nonzeros);
    for (WaveBlock& b : blocks) {
        matrix.column.insert(matrix.column.end(), b.columns.begin(), b.columns.end());
        std::vector<std::uint32_t>().swap(b.columns);
    }
    matrix.value.reserve(nonzeros);
    for (WaveBlock& b : blocks) {
        matrix.value.insert(matrix.value.end(), b.values.begin(), b.values.end());
        std::vector<float>().swap(b.values);
    }
    return matrix;
}

}  // namespace

FormFactorMatrix assemble_rows(std::size_t rows, const RowFunction& row, RowStats& stats,
                               Progress* progress) {
    std::vector<WaveBlock> blocks;
    std::vector<RowResult> wave;
    std::atomic<bool> cancelled{false};
    for (std::size_t first = 0; first < rows; first += kWaveRows) {
        const std::size_t count = std::min(kWaveRows, rows - first);
        wave.resize(count);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t k = r.begin(); k != r.end(); ++k) {
                                  if (cancelled || (progress && progress->cancelled())) {
                                      cancelled = true;
                                      return;
                                  }
                                  row(static_cast<std::uint32_t>(first + k), wave[k].entries, wave[k].stats);
                                  if (progress) progress->advance();
                              }
                          });
        if (cancelled) throw Cancelled{};
        blocks.push_back(compact(wave, stats));
    }
    return concatenate(blocks);
}

}  // namespace rad
