// The working parts of one point gather, shared by the gather's files: its near field (the
// patches beside the point, in pieces) and what the sum over its sources needs.
#pragma once

#include <radiosity/gather/gather.h>
#include <radiosity/gather/visibility_share.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace rayrad::radiosity {

/// One near patch of a gather.
struct Gatherer::NearPatch {
    uint32_t patch;
    uint32_t position;      ///< in its cluster's member tree order
    uint32_t first, count;  ///< its pieces in NearField::pieces
    double F;               ///< the whole patch's form factor seen from x
    /// The form factor of `piece`, when it is the whole patch, else −1 (not known).
    double known(const NearPiece& piece) const { return count == 1 && piece.depth == 0 ? F : -1; }
};

/// A cluster holding near patches, and their range in NearField::patches.
struct Gatherer::NearCluster {
    uint32_t cluster;
    size_t begin, end;
};

/// The near patches of one gather: linear luminance from corner values (refined toward x
/// with gathered midpoints when asked) where the rest of the sum takes patch-constant.
struct Gatherer::NearField {
    /// In cluster order; within a cluster sorted by tree position, so a member-tree node's
    /// near patches are a contiguous run.
    std::vector<NearPatch> patches;
    std::vector<NearPiece> pieces;      ///< every near patch's pieces, one run each
    std::vector<NearCluster> clusters;  ///< increasing
    using Iterator = std::vector<NearPatch>::const_iterator;
    /// Cluster c's near patches [first, last) (empty when it holds none).
    std::pair<Iterator, Iterator> of(uint32_t c) const {
        auto it = std::lower_bound(clusters.begin(), clusters.end(), c,
                                   [](const NearCluster& e, uint32_t k) { return e.cluster < k; });
        if (it == clusters.end() || it->cluster != c) return {patches.end(), patches.end()};
        return {patches.begin() + static_cast<std::ptrdiff_t>(it->begin),
                patches.begin() + static_cast<std::ptrdiff_t>(it->end)};
    }
};

/// What every source of one gather shares.
struct Gatherer::PointSources {
    PointSources(const Request& request, const NearField& near) : request(request), near(near) {}
    const Request& request;
    const NearField& near;
    /// A far node's error falls as (reach / r)³ (its expansion is of second order); an error
    /// in a gather of weight w reaches the sensor times w, so nodes may count as far from
    /// gatherFarDiameters · ∛w (never nearer than kLeastFarDiameters): the same error.
    double farDiameters = 0;
    /// A far source bringing less than this (lx: kWeakSourceShare of the light expected)
    /// takes one visibility ray.
    double weakBelow = 0;
    std::vector<uint32_t> sources{0};  ///< the scene itself (0), then the images i + 1 x faces
    size_t regions = 0;                ///< voxel regions (m_regions)
    /// Per image i and region r (i · regions + r): whether light may pass from the region
    /// through the image's chain to x.
    std::vector<char> regionOpen;

    /// A far source's visibility: up to four rays, or one in a re-gather (weight < 1), whose
    /// error reaches the sensor diminished. When x is expected to receive light (> 0; the
    /// caller's estimate), a source bringing less than weakBelow takes one ray (the error its
    /// visibility can bring is at most its light, and one ray's is unbiased), and any other
    /// four (unbiased, where two that agree would miss a small hidden part).
    VisibilityRays raysFor(const Rgb& e) const {
        if (request.weight < 1) return VisibilityRays::One;
        if (!(request.expected > 0)) return VisibilityRays::UpToFour;
        return luminance(e) < weakBelow ? VisibilityRays::One : VisibilityRays::Four;
    }
};

}  // namespace rayrad::radiosity
