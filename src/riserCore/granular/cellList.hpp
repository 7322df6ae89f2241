// riserCore: neighbour search for spheres by cells of side `cutoff` (a cell
// list; Allen & Tildesley, Computer Simulation of Liquids, 1987, sec. 5.3).
// Two centres closer than the cutoff lie in the same or in adjacent cells;
// each pair is visited once, through the cell itself and 13 of its 26
// neighbours. Only occupied cells are stored, sorted by their integer
// coordinates (z, then y, then x), so memory is O(N) however sparse or
// clustered the centres are; a build costs O(N log N) (a sort) and a visit
// O(N), against O(N^2) for all pairs. The cells are visited in that order:
// the key of a cell's neighbour at a given offset is the cell's key plus a
// constant, so the neighbours at each of the 13 offsets are met in the
// order of the keys, each found by a cursor that only moves forward. The
// pairs come in the order of space: a caller that numbers its centres
// along z reaches its data for each pair from nearby memory (with 1e5
// centres, a hash table's order cost a cache miss a pair, and its
// allocations dominated the builds of many small lists).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_GRANULAR_CELLLIST_HPP
#define RISERCORE_GRANULAR_CELLLIST_HPP

#include "checks.hpp"
#include "vector.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace riser {

class CellList
{
public:
    //- Sort the centres x into cells of side cutoff
    void build(const std::vector<Vector>& x, double cutoff)
    {
        requirePositive("riser::CellList", "cutoff", cutoff);
        side_ = cutoff;
        order_.clear();
        cells_.clear();
        if (x.empty()) return;
        lo_ = x[0];
        for (const Vector& p : x) lo_ = lo_.cwiseMin(p);
        order_.reserve(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) order_.emplace_back(cellKey(x[i]), i);
        std::sort(order_.begin(), order_.end());
        for (std::size_t a = 0; a < order_.size();)
        {
            std::size_t b = a + 1;
            while (b < order_.size() && order_[b].first == order_[a].first) ++b;
            cells_.push_back(Cell{order_[a].first, a, b});
            a = b;
        }
    }

    //- Call f(i, j) once for every pair i != j in the same or adjacent
    //  cells (every pair closer than the cutoff is among them)
    template<class PairFunction>
    void forEachPair(PairFunction&& f) const
    {
        static const std::array<std::array<int, 3>, 13> half = {{
            {{1, 0, 0}}, {{-1, 1, 0}}, {{0, 1, 0}}, {{1, 1, 0}},
            {{-1, -1, 1}}, {{0, -1, 1}}, {{1, -1, 1}}, {{-1, 0, 1}}, {{0, 0, 1}},
            {{1, 0, 1}}, {{-1, 1, 1}}, {{0, 1, 1}}, {{1, 1, 1}}
        }};
        // for each offset, the first cell whose key is not below the
        // neighbour's key of the cells visited so far
        std::array<std::size_t, 13> cursor{};
        for (const Cell& cell : cells_)
        {
            const std::uint64_t key = cell.key;
            const std::size_t a0 = cell.first, a1 = cell.end;
            for (std::size_t a = a0; a < a1; ++a)
            {
                for (std::size_t b = a + 1; b < a1; ++b) f(order_[a].second, order_[b].second);
            }
            const std::int64_t cx = coordinate(key, 0);
            const std::int64_t cy = coordinate(key, 1);
            const std::int64_t cz = coordinate(key, 2);
            for (std::size_t h = 0; h < half.size(); ++h)
            {
                const auto& o = half[h];
                if (cx + o[0] < 0 || cy + o[1] < 0 || cz + o[2] < 0) continue;
                const std::uint64_t k = pack(cx + o[0], cy + o[1], cz + o[2]);
                std::size_t& c = cursor[h];
                while (c < cells_.size() && cells_[c].key < k) ++c;
                if (c == cells_.size() || cells_[c].key != k) continue;
                const Cell* other = &cells_[c];
                for (std::size_t a = a0; a < a1; ++a)
                {
                    for (std::size_t b = other->first; b < other->end; ++b)
                    {
                        f(order_[a].second, order_[b].second);
                    }
                }
            }
        }
    }

    //- Number of occupied cells
    std::size_t cells() const { return cells_.size(); }

private:
    // 21 bits per coordinate: 2 million cells along each axis
    static constexpr int bits = 21;
    static constexpr std::int64_t mask = (std::int64_t(1) << bits) - 1;

    static std::uint64_t pack(std::int64_t cx, std::int64_t cy, std::int64_t cz)
    {
        return (std::uint64_t(cz) << (2*bits)) | (std::uint64_t(cy) << bits) | std::uint64_t(cx);
    }

    static std::int64_t coordinate(std::uint64_t key, int k)
    {
        return std::int64_t(key >> (k*bits)) & mask;
    }

    std::uint64_t cellKey(const Vector& p) const
    {
        std::int64_t c[3];
        for (int k = 0; k < 3; ++k)
        {
            const double s = std::floor((p[k] - lo_[k])/side_);
            // NaN and spans of 2^21 cells or more are refused
            requireInRange("riser::CellList", "(x - x_min)/cutoff", s,
                           0.0, Bound::closed, double(mask), Bound::open);
            c[k] = std::int64_t(s);
        }
        return pack(c[0], c[1], c[2]);
    }

    double side_ = 1.0;
    Vector lo_ = Vector::Zero();
    //- An occupied cell: its key, and its centres order_[first .. end)
    struct Cell
    {
        std::uint64_t key;
        std::size_t first, end;
    };

    std::vector<std::pair<std::uint64_t, std::size_t>> order_;
    std::vector<Cell> cells_;   //!< sorted by key
};

} // namespace riser

#endif
