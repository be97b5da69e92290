// What a frame of the culler did, counted: the work counters that guard its speed (a count does
// not move with the machine's load; tests/baselines/cull_work.tsv holds them per zone). Filled by
// the culler's stages (culler.h, row_word_boxes.h, region_blocks.h).
#pragma once

#include <cstdint>

namespace pvs {

struct CullWork {
    uint32_t row_words = 0; // words of a row (PVS, distance survivors) read
    uint32_t blocks = 0;    // boxes of blocks or of row words decided
    uint32_t boxes = 0;     // region boxes tested (a four-wide test counts four)

    CullWork& operator+=(const CullWork& o)
    {
        row_words += o.row_words, blocks += o.blocks, boxes += o.boxes;
        return *this;
    }
};

} // namespace pvs
