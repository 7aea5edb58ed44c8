// The lattice row of a flat grid index. Cells are stored column by column, c = x (rows + 2) + y + 1,
// so the row is c mod (rows + 2) - 1; the remainder is computed with two multiplications instead of
// a division (Lemire, Kaser & Kurz, "Faster remainder by direct computation", 2019).
#pragma once
#include <cstdint>

namespace granlub::automaton {

struct RowIndex {
    std::uint64_t magic = 0;
    std::uint32_t stride = 1;  // cells per column: rows + 2

    RowIndex() = default;
    explicit RowIndex(std::uint32_t column_length) : magic(~std::uint64_t{0} / column_length + 1), stride(column_length) {}

    int operator()(std::uint32_t c) const {
        __extension__ using u128 = unsigned __int128;
        const std::uint64_t low = magic * c;
        return static_cast<int>((static_cast<u128>(low) * stride) >> 64) - 1;
    }
};

}  // namespace granlub::automaton
