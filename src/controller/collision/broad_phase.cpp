#include "controller/collision/broad_phase.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace impetus::controller {

namespace {

/// Which coordinate the sweep runs along: 0 for x, 1 for y.
using Axis = Eigen::Index;

bool hasNaN(const Aabb& box)
{
    return std::isnan(box.lower.x()) || std::isnan(box.lower.y()) || std::isnan(box.upper.x()) ||
           std::isnan(box.upper.y());
}

/// The sort key of a proxy along `axis`. A NaN lower bound (a body that blew up) would break the
/// strict weak ordering std::sort needs, which is undefined behaviour; sending it to +∞ keeps the
/// order total. Boxes with a NaN anywhere are left out of the sweep: they overlap nothing, since
/// every comparison with NaN is false (Aabb::overlaps).
Scalar sortKey(const BroadPhaseProxy& proxy, Axis axis)
{
    const Scalar key = proxy.box.lower[axis];
    return std::isnan(key) ? std::numeric_limits<Scalar>::infinity() : key;
}

/// The sweep runs along the axis on which the box centres are most spread out (largest variance),
/// decided afresh on every call. The work of a sweep is the number of boxes whose intervals
/// overlap on the sweep axis, and spread-out centres make fewer of them. Two passes (mean, then
/// squared deviations) avoid the cancellation of E[c²] − E[c]² for worlds far from the origin.
/// Ties go to x. Boxes with a NaN are skipped, so that one blown-up body cannot decide the axis.
Axis chooseSweepAxis(std::span<const BroadPhaseProxy> proxies)
{
    Vec2 sum = Vec2::Zero();
    std::size_t count = 0;
    for (const BroadPhaseProxy& proxy : proxies) {
        if (hasNaN(proxy.box))
            continue;
        sum += proxy.box.lower + proxy.box.upper;
        ++count;
    }
    if (count == 0)
        return 0;
    const Vec2 mean = sum / (2 * static_cast<Scalar>(count)); // centres are (lower + upper)/2
    Vec2 squares = Vec2::Zero();
    for (const BroadPhaseProxy& proxy : proxies) {
        if (hasNaN(proxy.box))
            continue;
        const Vec2 d = (proxy.box.lower + proxy.box.upper) / 2 - mean;
        squares += d.cwiseProduct(d);
    }
    return squares.y() > squares.x() ? 1 : 0;
}

/// Bands across the other axis, each swept on its own.
///
/// A single sweep tests every pair whose intervals overlap on the sweep axis, however far apart
/// the boxes are on the other one. For layouts that fill both axes that is O(n·√n): in the 20 × 20
/// grid of pyramids, a box shares its x interval with the boxes of its column in all twenty rows
/// of pyramids, and its y interval with everything in its row across all twenty columns, so either
/// sweep makes 4 million tests for 58,000 overlapping pairs. Cutting the other axis into strips a
/// few boxes high, and sweeping each strip, leaves only the boxes near each other on both axes.
/// A box goes into every strip its interval on the other axis touches.
struct Strips {
    Scalar origin = 0; ///< where strip 0 begins on the other axis, m
    Scalar height = 1; ///< m
    std::size_t count = 1;

    /// The strip that holds coordinate `y` (on the other axis); values outside go to the end strips.
    /// Clamped in floating point first: converting ±∞ to an integer is undefined behaviour.
    std::size_t of(Scalar y) const
    {
        const Scalar t = (y - origin) / height;
        if (!(t >= 1))
            return 0;
        if (t >= static_cast<Scalar>(count))
            return count - 1;
        return static_cast<std::size_t>(t);
    }
};

/// Strips of about kBroadPhaseStripHeight mean box sizes, but no more than √n of them, so that
/// each strip holds √n boxes on average and the bookkeeping per strip stays small next to the
/// sweep. Few proxies, or an infinite extent, give one strip: the plain sweep.
Strips chooseStrips(std::span<const BroadPhaseProxy> proxies, Axis other)
{
    Strips strips;
    if (proxies.size() < static_cast<std::size_t>(constants::kBroadPhaseMinProxiesForStrips))
        return strips;
    Scalar lowest = std::numeric_limits<Scalar>::infinity();
    Scalar highest = -lowest;
    Scalar extentSum = 0;
    std::size_t count = 0;
    for (const BroadPhaseProxy& proxy : proxies) {
        if (hasNaN(proxy.box))
            continue;
        lowest = std::min(lowest, proxy.box.lower[other]);
        highest = std::max(highest, proxy.box.upper[other]);
        extentSum += proxy.box.upper[other] - proxy.box.lower[other];
        ++count;
    }
    const Scalar span = highest - lowest;
    if (count == 0 || !std::isfinite(span) || !std::isfinite(extentSum) || !(span > 0))
        return strips;
    const Scalar meanExtent = extentSum / static_cast<Scalar>(count);
    const Scalar height =
        std::max(constants::kBroadPhaseStripHeight * meanExtent, span / std::sqrt(static_cast<Scalar>(count)));
    strips.origin = lowest;
    strips.height = height;
    strips.count = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(span / height)));
    return strips;
}

/// Sorts `order` by (key, index) with insertion sort, which is linear when the order is already
/// nearly right, as it is from one step to the next. Gives up, leaving `order` a permutation in
/// some partial order, once it has moved more than `budget` entries: the order was far from right
/// (new proxies, a changed sweep axis, a scene that exploded) and std::sort is the better tool.
/// Returns true when `order` is sorted.
template <typename Less>
bool insertionSortWithin(std::vector<std::uint32_t>& order, Less less, std::size_t budget)
{
    std::size_t moves = 0;
    for (std::size_t i = 1; i < order.size(); ++i) {
        const std::uint32_t item = order[i];
        std::size_t j = i;
        while (j > 0 && less(item, order[j - 1])) {
            order[j] = order[j - 1];
            --j;
            if (++moves > budget) {
                order[j] = item;
                return false;
            }
        }
        order[j] = item;
    }
    return true;
}

/// Sorts pairs by (first, second) in O(n + pairs): a counting sort by `first` (n buckets), then
/// each bucket by `second`. A comparison sort of the 58,000 pairs of the pyramid grid cost as much
/// as the whole sweep; the buckets here hold a box's few neighbours (a ground's few hundred), so
/// sorting them is cheap, with std::sort kept for a bucket that is large.
void sortPairs(std::vector<ProxyPair>& pairs, std::size_t proxyCount, std::vector<std::size_t>& start,
               std::vector<std::size_t>& cursor, std::vector<std::uint32_t>& seconds)
{
    start.assign(proxyCount + 1, 0);
    for (const ProxyPair& pair : pairs)
        ++start[pair.first + 1];
    for (std::size_t i = 0; i < proxyCount; ++i)
        start[i + 1] += start[i];
    seconds.resize(pairs.size());
    cursor.assign(start.begin(), start.end() - 1);
    for (const ProxyPair& pair : pairs)
        seconds[cursor[pair.first]++] = pair.second;
    for (std::size_t first = 0; first < proxyCount; ++first) {
        const auto begin = seconds.begin() + static_cast<std::ptrdiff_t>(start[first]);
        const auto end = seconds.begin() + static_cast<std::ptrdiff_t>(start[first + 1]);
        constexpr std::ptrdiff_t kInsertionSortLimit = 32;
        if (end - begin > kInsertionSortLimit) {
            std::sort(begin, end);
        } else {
            for (auto i = begin; i != end; ++i) {
                const std::uint32_t item = *i;
                auto j = i;
                for (; j != begin && item < *(j - 1); --j)
                    *j = *(j - 1);
                *j = item;
            }
        }
        for (std::size_t k = start[first]; k < start[first + 1]; ++k)
            pairs[k] = ProxyPair{static_cast<std::uint32_t>(first), seconds[k]};
    }
}

/// The box enlarged on every side by kBroadPhaseFatFraction of its smaller side. Scaled by the box
/// so that a pebble and a boulder both get room for a few steps of their own jitter, and by the
/// smaller side so that a long ground or wall does not get a margin as large as the boxes on it.
/// The margin is zero when it would not be finite (an infinite box), and a box with a NaN stays as
/// it is, so that the sweep leaves it out as it would the box itself. The lower corner is taken
/// as the smaller of the two corners (the larger for the upper), so that even an inverted box
/// (lower > upper, never made by the engine) lies inside its fat box.
Aabb fatten(const Aabb& box)
{
    if (hasNaN(box))
        return box;
    const Vec2 lower = box.lower.cwiseMin(box.upper);
    const Vec2 upper = box.lower.cwiseMax(box.upper);
    const Vec2 extent = upper - lower;
    Scalar margin = constants::kBroadPhaseFatFraction * std::min(extent.x(), extent.y());
    if (!std::isfinite(margin))
        margin = 0;
    return Aabb{lower - Vec2::Constant(margin), upper + Vec2::Constant(margin)};
}

} // namespace

bool BroadPhase::fatBoxesHold(std::span<const BroadPhaseProxy> proxies) const
{
    if (proxies.size() != m_fat.size())
        return false;
    for (std::size_t i = 0; i < proxies.size(); ++i) {
        const BroadPhaseProxy& proxy = proxies[i];
        const BroadPhaseProxy& fat = m_fat[i];
        // Written so that every comparison with a NaN fails: a NaN box is never inside.
        const bool inside = fat.box.lower.x() <= proxy.box.lower.x() && fat.box.lower.y() <= proxy.box.lower.y() &&
                            proxy.box.upper.x() <= fat.box.upper.x() && proxy.box.upper.y() <= fat.box.upper.y();
        if (!inside || proxy.body != fat.body || proxy.fixed != fat.fixed)
            return false;
    }
    return true;
}

void BroadPhase::findPairs(std::span<const BroadPhaseProxy> proxies, std::vector<ProxyPair>& pairs)
{
    m_reused = fatBoxesHold(proxies);
    if (!m_reused) {
        m_fat.resize(proxies.size());
        for (std::size_t i = 0; i < proxies.size(); ++i)
            m_fat[i] = BroadPhaseProxy{fatten(proxies[i].box), proxies[i].body, proxies[i].fixed};
        sweep(m_fat, m_fatPairs);
    }
    // Every box is inside its fat box here (or has a NaN, and then it overlaps nothing), so the
    // fat pairs hold every overlapping pair, and the same-body and two-fixed rules already hold
    // for them. Filtering keeps their sorted order. Every pair is written and the count moves on
    // only for those that overlap: in a settling pile about half do, at random, and a branch on
    // each would be mispredicted that often.
    pairs.resize(m_fatPairs.size());
    std::size_t kept = 0;
    for (const ProxyPair& pair : m_fatPairs) {
        pairs[kept] = pair;
        kept += proxies[pair.first].box.overlaps(proxies[pair.second].box) ? 1 : 0;
    }
    pairs.resize(kept);
}

void BroadPhase::sweep(std::span<const BroadPhaseProxy> proxies, std::vector<ProxyPair>& pairs)
{
    pairs.clear();
    const std::size_t n = proxies.size();
    const Axis axis = chooseSweepAxis(proxies);
    const Axis other = 1 - axis;

    // Ties in the key are broken by index, so the order is a total order that any correct sort
    // reaches: insertion sort from last step's order and std::sort from scratch agree exactly.
    const auto less = [&](std::uint32_t a, std::uint32_t b) {
        const Scalar ka = sortKey(proxies[a], axis);
        const Scalar kb = sortKey(proxies[b], axis);
        return ka < kb || (ka == kb && a < b);
    };

    // Last step's order is only a permutation of this step's proxies if the count is unchanged.
    bool sorted = false;
    if (m_order.size() == n) {
        const auto budget =
            static_cast<std::size_t>(constants::kBroadPhaseInsertionMovesPerProxy * static_cast<Scalar>(n));
        sorted = insertionSortWithin(m_order, less, budget);
    } else {
        m_order.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            m_order[i] = static_cast<std::uint32_t>(i);
    }
    if (!sorted)
        std::sort(m_order.begin(), m_order.end(), less);

    // Deal the proxies into their strips in sorted order (a counting sort by strip, which is
    // stable), so that each strip's run of entries is itself sorted along the sweep axis.
    const Strips strips = chooseStrips(proxies, other);
    std::vector<std::size_t>& stripStart = m_stripStart;
    stripStart.assign(strips.count + 1, 0);
    for (const BroadPhaseProxy& proxy : proxies) {
        if (hasNaN(proxy.box))
            continue;
        for (std::size_t s = strips.of(proxy.box.lower[other]); s <= strips.of(proxy.box.upper[other]); ++s)
            ++stripStart[s + 1];
    }
    for (std::size_t s = 0; s < strips.count; ++s)
        stripStart[s + 1] += stripStart[s];
    std::vector<SweepEntry>& entries = m_entries;
    entries.resize(stripStart.back());
    std::vector<std::size_t>& cursor = m_cursor;
    cursor.assign(stripStart.begin(), stripStart.end() - 1);
    for (const std::uint32_t i : m_order) {
        const BroadPhaseProxy& proxy = proxies[i];
        if (hasNaN(proxy.box))
            continue;
        const SweepEntry entry{proxy.box.lower[axis], proxy.box.upper[axis], proxy.box.lower[other],
                               proxy.box.upper[other], i, proxy.body, proxy.fixed};
        for (std::size_t s = strips.of(entry.otherLower); s <= strips.of(entry.otherUpper); ++s)
            entries[cursor[s]++] = entry;
    }

    for (std::size_t s = 0; s < strips.count; ++s) {
        const std::size_t end = stripStart[s + 1];
        // Every box whose lower end lies within [lower, upper] of an earlier box overlaps it on
        // the sweep axis; `<=` because touching boxes count as overlapping (Aabb::overlaps). Boxes
        // met later have larger lower ends, so the inner loop stops at the first that starts beyond.
        for (std::size_t k = stripStart[s]; k < end; ++k) {
            const SweepEntry& a = entries[k];
            for (std::size_t m = k + 1; m < end && entries[m].lower <= a.upper; ++m) {
                const SweepEntry& b = entries[m];
                if (b.otherLower > a.otherUpper || a.otherLower > b.otherUpper)
                    continue;
                if (a.body == b.body || (a.fixed && b.fixed))
                    continue;
                // Two boxes that overlap share the point max(lowers) on the other axis, and both
                // are in that point's strip; reporting the pair there alone reports it once.
                if (strips.count > 1 && strips.of(std::max(a.otherLower, b.otherLower)) != s)
                    continue;
                pairs.push_back(a.index < b.index ? ProxyPair{a.index, b.index} : ProxyPair{b.index, a.index});
            }
        }
    }

    // The sweep emits pairs in sweep order, which depends on positions; the contract promises
    // (first, second) order so that the solver visits contacts the same way whatever happened before.
    sortPairs(pairs, n, m_pairStart, m_cursor, m_seconds);
}

} // namespace impetus::controller
