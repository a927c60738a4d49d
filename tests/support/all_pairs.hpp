// Neighbour lists of every pair of particles closer than a radius, by brute force, in the particles' own
// order (no sort): for tests on small sets whose order must stay as built (sub-domains with their ghosts
// at the end).
#pragma once

#include <vector>

#include "grit/neighbors/neighbor_list.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::testing {

template <int Dim>
neighbors::NeighborList<Dim> all_pairs(const particles::SphParticles<Dim>& ps, double radius) {
    std::vector<Index> offsets{0}, indices;
    for (Index i = 0; i < ps.size(); ++i) {
        for (Index j = 0; j < ps.size(); ++j)
            if (j != i && core::norm2(ps.position()[i] - ps.position()[j]) < radius * radius) indices.push_back(j);
        offsets.push_back(static_cast<Index>(indices.size()));
    }
    neighbors::NeighborList<Dim> list;
    list.assign(offsets, indices, std::vector<core::Vec<Dim>>(ps.position(), ps.position() + ps.size()));
    return list;
}

}  // namespace grit::testing
