// The DEM settling set-up of bench/peers/liggghts/in.dem_settle, reproduced grain for grain:
// d = 3 mm spheres (rho 2500, E 5 MPa, nu 0.45, e 0.3, mu 0.5) on a simple-cubic lattice of spacing
// s = 1.1 d in a box periodic in x and y (L = nxy s), layers k s for k = 1..nz, each grain moved in x
// and y by LAMMPS' `displace_atoms random 0.0003 0.0003 0.0 15485863` (the same numbers: the Park-Miller
// generator reseeded from a hash of the seed and the grain's coordinates), Hertz-Mindlin with
// tangential history, a Hertz plane wall at z = 0, gravity 9.81, skin 1 mm, dt = 1e-5 s.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "grit/dem/dem_system.hpp"

namespace grit::bench {

/// A number as LAMMPS substitutes an equal-style variable into a command (printf "%.15g").
inline double as_lammps_text(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.15g", v);
    return std::strtod(text, nullptr);
}

/// LAMMPS' RanPark (Park-Miller minimal standard) with its reset(seed, coord): a one-at-a-time hash
/// of the seed's and the coordinates' bytes (as signed chars), kept to 27 bits, then 5 warm-up draws.
class ParkMiller {
public:
    ParkMiller(int seed, const double coord[3]) {
        std::uint32_t hash = 0;
        auto mix = [&](const void* p, std::size_t n) {
            const auto* bytes = static_cast<const signed char*>(p);
            for (std::size_t k = 0; k < n; ++k) {
                hash += static_cast<std::uint32_t>(static_cast<int>(bytes[k]));
                hash += hash << 10;
                hash ^= hash >> 6;
            }
        };
        mix(&seed, sizeof seed);
        mix(coord, 3 * sizeof(double));
        hash += hash << 3;
        hash ^= hash >> 11;
        hash += hash << 15;
        state_ = static_cast<int>(hash & 0x7ffffff);
        if (state_ == 0) state_ = 1;
        for (int k = 0; k < 5; ++k) uniform();
    }
    double uniform() {
        const int k = state_ / 127773;
        state_ = 16807 * (state_ - k * 127773) - 2836 * k;
        if (state_ < 0) state_ += 2147483647;
        return state_ * (1.0 / 2147483647);
    }

private:
    int state_ = 1;
};

/// The in.dem_settle system with nxy x nxy x nz grains.
inline dem::DemSystem<3> dem_settle(int nxy, int nz) {
    const double d = 0.003;
    const double s = as_lammps_text(1.1 * d);
    const double length = as_lammps_text(nxy * s);
    const double zlo = as_lammps_text(0.6 * s), zhi = as_lammps_text((nz + 0.5) * s);
    const double height = as_lammps_text((nz + 2) * s * 1.5);
    dem::DemParameters<3> p;
    p.contact_law = "hertz";
    p.gravity = {{0.0, 0.0, -9.81}};
    p.skin = 0.001;
    p.domain.periodic = {true, true, false};
    p.domain.lower = {{0.0, 0.0, 0.0}};
    p.domain.upper = {{length, length, height}};
    dem::DemSystem<3> sys(p, {dem::GrainMaterial{"dem_settle", 2500.0, 5e6, 0.45, 0.5, 0.3, d}});
    // create_atoms order: z, then y, then x fastest; points on the periodic upper faces are left out.
    for (int k = 0; k * s <= zhi; ++k)
        for (int j = 0; j * s < length; ++j)
            for (int i = 0; i * s < length; ++i) {
                double x[3] = {i * s, j * s, k * s};
                if (x[2] < zlo) continue;
                ParkMiller random(15485863, x);
                x[0] += 0.0003 * 2.0 * (random.uniform() - 0.5);
                x[1] += 0.0003 * 2.0 * (random.uniform() - 0.5);
                sys.add_grain(core::Vec<3>{{x[0], x[1], x[2]}}, 0.5 * d, 0);
            }
    sys.add_wall({core::Vec<3>::zero(), core::Vec<3>{{0.0, 0.0, 1.0}}, 0});
    return sys;
}

}  // namespace grit::bench
