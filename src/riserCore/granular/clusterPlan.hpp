// riserCore: the plan of a flow step's contact sub-steps. Grains that may
// touch each other within the step form clusters (the connected components
// of the graph of such pairs), and every grain of a cluster takes the
// largest need of sub-steps among its members, so that a cluster is
// sub-stepped as one. Union-find with path halving: joining the n grains of
// a step costs O(n alpha(n)).
//
// A grain's need is the number of sub-steps its own contacts ask for (0:
// none; the wall's need is set at construction, each pair's by join). A
// cluster that extends beyond what one caller holds (another processor's
// grains) is completed by raise: the caller hands each grain the larger
// need another holder found for it, and spreads again, until no need grows
// anywhere.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_GRANULAR_CLUSTERPLAN_HPP
#define RISERCORE_GRANULAR_CLUSTERPLAN_HPP

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace riser {

class ClusterPlan
{
public:
    //- The grains with their own needs (the wall's: 0 for none)
    explicit ClusterPlan(std::vector<long> need)
    :
        need_(std::move(need)),
        root_(need_.size()),
        clustered_(need_.size(), false)
    {
        std::iota(root_.begin(), root_.end(), std::size_t(0));
    }

    std::size_t size() const { return need_.size(); }

    //- Grains i and j may touch within the step, their contact needing k
    //  sub-steps: each needs at least k, and they are one cluster
    void join(std::size_t i, std::size_t j, long k)
    {
        check(i);
        check(j);
        if (i == j)
        {
            throw std::invalid_argument("riser::ClusterPlan::join: a grain with itself");
        }
        need_[i] = std::max(need_[i], k);
        need_[j] = std::max(need_[j], k);
        clustered_[i] = clustered_[j] = true;
        root_[find(i)] = find(j);
    }

    //- Every grain's need raised to its cluster's largest; whether the need
    //  of one of the first nWatched grains grew
    bool spread(std::size_t nWatched)
    {
        const std::size_t n = need_.size();
        std::vector<long> largest(n, 0);
        for (std::size_t i = 0; i < n; ++i)
        {
            long& l = largest[find(i)];
            l = std::max(l, need_[i]);
        }
        bool grown = false;
        for (std::size_t i = 0; i < n; ++i)
        {
            const long l = largest[find(i)];
            grown = grown || (i < nWatched && l > need_[i]);
            need_[i] = l;
        }
        return grown;
    }

    //- Grain i needs at least k (found by another holder of its cluster);
    //  whether its need grew
    bool raise(std::size_t i, long k)
    {
        check(i);
        if (k <= need_[i])
        {
            return false;
        }
        need_[i] = k;
        return true;
    }

    long need(std::size_t i) const { check(i); return need_[i]; }

    //- Whether grain i may touch another grain within the step
    bool clustered(std::size_t i) const { check(i); return clustered_[i]; }

    //- Whether grains i and j are in one cluster (of the pairs joined)
    bool together(std::size_t i, std::size_t j)
    {
        check(i);
        check(j);
        return find(i) == find(j);
    }

    //- The cluster of grain i, named by one of its grains: the same for
    //  the grains of one cluster, different for those of two
    std::size_t cluster(std::size_t i)
    {
        check(i);
        return find(i);
    }

private:
    void check(std::size_t i) const
    {
        if (i >= need_.size())
        {
            throw std::out_of_range("riser::ClusterPlan: grain index beyond the grains");
        }
    }

    std::size_t find(std::size_t i)
    {
        while (root_[i] != i)
        {
            root_[i] = root_[root_[i]];
            i = root_[i];
        }
        return i;
    }

    std::vector<long> need_;
    std::vector<std::size_t> root_;
    std::vector<bool> clustered_;
};

}  // namespace riser

#endif
