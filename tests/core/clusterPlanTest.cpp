// Tests of the contact sub-step planner (src/riserCore/granular/clusterPlan.hpp):
// the clusters and their needs against hand-worked cases, and against an
// independent breadth-first search over random graphs, whole and split
// between two holders that exchange the needs of the grains both hold.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "granular/clusterPlan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <queue>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

using namespace riser;

namespace {

struct Edge { std::size_t i, j; long k; };

// Each grain's need by breadth-first search: the largest of its component's
// own needs and pair needs (the definition, written independently)
std::vector<long> needsBySearch(const std::vector<long>& own, const std::vector<Edge>& edges)
{
    const std::size_t n = own.size();
    std::vector<std::vector<std::size_t>> next(n);
    std::vector<long> incident(own);
    for (const Edge& e : edges)
    {
        next[e.i].push_back(e.j);
        next[e.j].push_back(e.i);
        incident[e.i] = std::max(incident[e.i], e.k);
        incident[e.j] = std::max(incident[e.j], e.k);
    }
    std::vector<long> result(n, -1);
    for (std::size_t s = 0; s < n; ++s)
    {
        if (result[s] >= 0) continue;
        std::vector<std::size_t> component{s};
        std::vector<bool> seen(n, false);
        seen[s] = true;
        std::queue<std::size_t> q;
        q.push(s);
        long largest = 0;
        while (!q.empty())
        {
            const std::size_t a = q.front();
            q.pop();
            largest = std::max(largest, incident[a]);
            for (const std::size_t b : next[a])
            {
                if (!seen[b])
                {
                    seen[b] = true;
                    component.push_back(b);
                    q.push(b);
                }
            }
        }
        for (const std::size_t a : component) result[a] = largest;
    }
    return result;
}

std::vector<Edge> randomEdges(std::mt19937& rng, std::size_t n, std::size_t m)
{
    std::uniform_int_distribution<std::size_t> grain(0, n - 1);
    std::uniform_int_distribution<long> need(1, 500);
    std::vector<Edge> edges;
    while (edges.size() < m)
    {
        const std::size_t i = grain(rng), j = grain(rng);
        if (i != j) edges.push_back({i, j, need(rng)});
    }
    return edges;
}

std::vector<long> randomOwnNeeds(std::mt19937& rng, std::size_t n)
{
    // most grains far from the wall (0), some near it
    std::uniform_int_distribution<long> need(0, 800);
    std::vector<long> own(n);
    for (long& k : own) { k = need(rng); if (k < 600) k = 0; }
    return own;
}

}  // namespace

TEST(ClusterPlan, AChainTakesItsLargestNeedAndALoneGrainKeepsItsOwn)
{
    // 0 - 1 - 2 a chain (pair needs 40 and 90), 3 alone at the wall (120),
    // 4 alone and far from everything (0)
    ClusterPlan plan({0, 0, 0, 120, 0});
    plan.join(0, 1, 40);
    plan.join(2, 1, 90);
    EXPECT_TRUE(plan.spread(5));  // grain 0 grew from 40 to 90
    for (std::size_t i : {0, 1, 2}) EXPECT_EQ(plan.need(i), 90);
    EXPECT_EQ(plan.need(3), 120);
    EXPECT_EQ(plan.need(4), 0);
    for (std::size_t i : {0, 1, 2}) EXPECT_TRUE(plan.clustered(i));
    EXPECT_FALSE(plan.clustered(3));
    EXPECT_FALSE(plan.clustered(4));
    EXPECT_TRUE(plan.together(0, 2));
    EXPECT_FALSE(plan.together(0, 3));
    // nothing left to spread
    EXPECT_FALSE(plan.spread(5));
}

TEST(ClusterPlan, AWallNeedInAClusterIsEveryMembersNeed)
{
    ClusterPlan plan({0, 300, 0});
    plan.join(0, 1, 50);
    plan.join(1, 2, 60);
    plan.spread(3);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(plan.need(i), 300);
}

TEST(ClusterPlan, OnlyTheWatchedGrainsCountAsGrown)
{
    // grain 2 (not watched: another holder's copy) grows, 0 and 1 do not
    ClusterPlan plan({70, 70, 0});
    plan.join(0, 1, 10);
    plan.join(1, 2, 10);
    EXPECT_FALSE(plan.spread(2));
    EXPECT_EQ(plan.need(2), 70);
    EXPECT_FALSE(plan.spread(3));
}

TEST(ClusterPlan, RaiseReportsGrowthOnly)
{
    ClusterPlan plan({5, 0});
    EXPECT_FALSE(plan.raise(0, 5));
    EXPECT_FALSE(plan.raise(0, 3));
    EXPECT_TRUE(plan.raise(1, 8));
    EXPECT_EQ(plan.need(1), 8);
    EXPECT_EQ(plan.need(0), 5);
}

TEST(ClusterPlan, RandomGraphsEqualABreadthFirstSearch)
{
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 200; ++trial)
    {
        const std::size_t n = 1 + rng() % 300;
        const std::size_t m = n > 1 ? rng() % (n + n/2) : 0;
        const std::vector<long> own = randomOwnNeeds(rng, n);
        const std::vector<Edge> edges = n > 1 ? randomEdges(rng, n, m) : std::vector<Edge>{};
        ClusterPlan plan(own);
        for (const Edge& e : edges) plan.join(e.i, e.j, e.k);
        plan.spread(n);
        const std::vector<long> expected = needsBySearch(own, edges);
        for (std::size_t i = 0; i < n; ++i)
        {
            ASSERT_EQ(plan.need(i), expected[i]) << "trial " << trial << ", grain " << i;
        }
        // one spread completes a plan held whole
        EXPECT_FALSE(plan.spread(n));
    }
}

// Two holders (processors) split the grains; each holds its own grains and
// copies of the other's grains that share an edge with one of its own, and
// joins the edges with one of its own grains in them. They exchange the needs
// of the copies' originals and raise, as the riser cloud does, until neither
// grows: the needs then equal the whole graph's, although a cluster may wind
// between the two holders many times.
TEST(ClusterPlan, SplitBetweenTwoHoldersEqualsTheWholeGraph)
{
    std::mt19937 rng(77);
    for (int trial = 0; trial < 100; ++trial)
    {
        const std::size_t n = 2 + rng() % 200;
        const std::vector<long> own = randomOwnNeeds(rng, n);
        const std::vector<Edge> edges = randomEdges(rng, n, n);
        std::vector<int> holder(n);
        for (int& h : holder) h = rng() % 2;

        // each holder's grains: its own first, then its copies; and the map
        // from a global grain to its index there (-1: not held)
        struct Held { std::vector<std::size_t> grain; std::vector<long> index; std::size_t nOwn; };
        std::vector<Held> held(2);
        for (int h = 0; h < 2; ++h)
        {
            Held& H = held[h];
            H.index.assign(n, -1);
            for (std::size_t g = 0; g < n; ++g)
                if (holder[g] == h) { H.index[g] = H.grain.size(); H.grain.push_back(g); }
            H.nOwn = H.grain.size();
            for (const Edge& e : edges)
                for (const auto& [a, b] : {std::pair{e.i, e.j}, std::pair{e.j, e.i}})
                    if (holder[a] == h && holder[b] != h && H.index[b] < 0)
                    { H.index[b] = H.grain.size(); H.grain.push_back(b); }
        }
        std::vector<ClusterPlan> plans;
        for (int h = 0; h < 2; ++h)
        {
            std::vector<long> needs;
            for (const std::size_t g : held[h].grain) needs.push_back(own[g]);
            plans.emplace_back(needs);
            for (const Edge& e : edges)
                if (holder[e.i] == h || holder[e.j] == h)
                    plans[h].join(held[h].index[e.i], held[h].index[e.j], e.k);
        }
        int rounds = 0;
        for (bool grown = true; grown; ++rounds)
        {
            ASSERT_LT(rounds, int(n) + 2) << "no end to the exchange";
            grown = false;
            for (int h = 0; h < 2; ++h) grown = plans[h].spread(held[h].nOwn) || grown;
            // each holder raises its copies to the needs their holder found
            for (int h = 0; h < 2; ++h)
            {
                const int o = 1 - h;
                for (std::size_t c = held[h].nOwn; c < held[h].grain.size(); ++c)
                {
                    const std::size_t g = held[h].grain[c];
                    grown = plans[h].raise(c, plans[o].need(held[o].index[g])) || grown;
                }
            }
        }
        const std::vector<long> expected = needsBySearch(own, edges);
        for (int h = 0; h < 2; ++h)
            for (std::size_t c = 0; c < held[h].nOwn; ++c)
                ASSERT_EQ(plans[h].need(c), expected[held[h].grain[c]])
                    << "trial " << trial << ", holder " << h;
    }
}

TEST(ClusterPlan, RefusesGrainsItDoesNotHold)
{
    ClusterPlan plan({0, 0});
    EXPECT_THROW(plan.join(0, 2, 1), std::out_of_range);
    EXPECT_THROW(plan.join(1, 1, 1), std::invalid_argument);
    EXPECT_THROW(plan.raise(5, 1), std::out_of_range);
    EXPECT_THROW(plan.need(2), std::out_of_range);
}

TEST(ClusterPlan, EachGrainsClusterNamesItsComponent)
{
    // cluster(i) == cluster(j) exactly when a breadth-first search finds i
    // and j connected (grains as their own needs' labels: each grain's need
    // is its index, so the search's largest need of a component names it)
    std::mt19937 rng(31);
    for (int trial = 0; trial < 100; ++trial)
    {
        const std::size_t n = 2 + rng() % 200;
        const std::vector<Edge> edges = randomEdges(rng, n, rng() % n);
        std::vector<long> index(n);
        for (std::size_t i = 0; i < n; ++i) index[i] = long(i);
        std::vector<Edge> unweighted;
        for (const Edge& e : edges) unweighted.push_back({e.i, e.j, 0});
        const std::vector<long> component = needsBySearch(index, unweighted);
        ClusterPlan plan(std::vector<long>(n, 0));
        for (const Edge& e : edges) plan.join(e.i, e.j, 0);
        for (std::size_t i = 0; i < n; ++i)
        {
            for (std::size_t j = i + 1; j < n; ++j)
            {
                ASSERT_EQ(plan.cluster(i) == plan.cluster(j), component[i] == component[j])
                    << "trial " << trial << ", grains " << i << " and " << j;
            }
        }
    }
}
