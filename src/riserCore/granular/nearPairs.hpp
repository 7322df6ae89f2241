// riserCore: the pairs of spheres whose centres may lie closer than a
// cutoff, in open space or in a section periodic along z (length L from z0),
// found by a cell list (granular/cellList.hpp). In a periodic section the
// centres within the cutoff of an end get an image shifted by +L or -L, so
// that a pair across the ends is found through one of its members' images;
// it is visited once, through the image of the larger index. The section
// must be longer than twice the cutoff (else a sphere could meet another
// through both ends, or its own image).
//
// Each pair is given as (i, j, dz) with i < j and dz the z shift of the
// image of j nearest i (0 for a pair that does not cross the ends): the
// candidate separation is x_j + dz e_z - x_i. Every pair closer than the
// cutoff is visited; farther ones may be (the caller tests the distance).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_GRANULAR_NEARPAIRS_HPP
#define RISERCORE_GRANULAR_NEARPAIRS_HPP

#include "granular/cellList.hpp"

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace riser {

//- The separation d of two points as seen through the images of the second
//  in a section periodic along z of length L (L = 0: open space): its z
//  reduced by a whole number of L to the nearest image, in [-L/2, L/2]
inline Vector nearestImage(Vector d, double L)
{
    if (L > 0.0) d.z() -= L*std::round(d.z()/L);
    return d;
}

class NearPairs
{
public:
    //- A section periodic along z from z0, of length L (L = 0: none)
    void setPeriodic(double z0, double L)
    {
        requireNonNegative("riser::NearPairs", "periodic length L", L);
        z0_ = z0;
        length_ = L;
    }

    //- Call f(i, j, dz) for the pairs of centres x that may lie closer
    //  than cutoff
    template<class PairFunction>
    void forEachPair(const std::vector<Vector>& x, double cutoff, PairFunction&& f)
    {
        const std::size_t n = x.size();
        if (n == 0) return;
        all_.assign(x.begin(), x.end());
        original_.resize(n);
        shift_.assign(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) original_[i] = i;
        if (length_ > 0.0)
        {
            requireInRange("riser::NearPairs", "periodic length L / (2 cutoff)",
                           length_/(2.0*cutoff), 1.0, Bound::open, 1e300, Bound::closed);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double z = x[i].z();
                for (const double dz : {length_, -length_})
                {
                    const bool nearEnd =
                        dz > 0.0 ? z - z0_ < cutoff : z0_ + length_ - z < cutoff;
                    if (!nearEnd) continue;
                    all_.push_back(x[i] + Vector(0.0, 0.0, dz));
                    original_.push_back(i);
                    shift_.push_back(dz);
                }
            }
        }
        cells_.build(all_, cutoff);
        cells_.forEachPair([&](std::size_t a, std::size_t b)
        {
            if (a >= n && b >= n) return;  // two images: met through an original
            if (a >= n) std::swap(a, b);
            std::size_t i = original_[a], j = original_[b];
            double dz = shift_[b];
            // a pair across the ends is met twice (i with j's image, j with
            // i's): kept once, through the image of the larger index
            if (i == j || (b >= n && j < i)) return;
            if (j < i)
            {
                std::swap(i, j);
                dz = -dz;
            }
            f(i, j, dz);
        });
    }

private:
    double z0_ = 0.0, length_ = 0.0;
    std::vector<Vector> all_;           //!< the centres and their images
    std::vector<std::size_t> original_; //!< the centre of each of all_
    std::vector<double> shift_;         //!< the image's z shift
    CellList cells_;
};

} // namespace riser

#endif
