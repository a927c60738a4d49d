// The DEM grain set: discs (2D) or spheres (3D) as named structure-of-arrays fields of one registry,
// so sorting by cell, removal, insertion and output carry every field (and any a coupling adds).
#pragma once

#include <cstdint>
#include <numbers>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/grain_material.hpp"
#include "grit/dem/spin.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/particles/field_registry.hpp"
#include "grit/particles/particle_set.hpp"

namespace grit::dem {

/// Mass of the sphere of radius r, rho 4/3 pi r^3 [kg].
constexpr double sphere_mass(double density, double radius) noexcept {
    return density * (4.0 / 3.0) * std::numbers::pi * radius * radius * radius;
}

/// Mass of a grain of radius r: a sphere rho 4/3 pi r^3 in 3D; in 2D a disc per metre of thickness,
/// rho pi r^2 [kg/m] (2D masses, forces and torques are per metre of thickness, as in the SPH set).
template <int Dim>
constexpr double grain_mass(double density, double radius) noexcept {
    if constexpr (Dim == 2) return density * std::numbers::pi * radius * radius;
    else return sphere_mass(density, radius);
}

/// The mass a grain's contacts are evaluated with: the sphere of its radius in 2D and 3D alike ("a disc
/// collides like the sphere of its diameter", docs/theory.md). From the grain's own mass m: m in 3D,
/// m 4/3 r in 2D (the disc's rho pi r^2 per metre times 4/3 r is rho 4/3 pi r^3).
template <int Dim>
constexpr double contact_mass(double mass, double radius) noexcept {
    if constexpr (Dim == 2) return mass * ((4.0 / 3.0) * radius);
    else return mass;
}

/// Moment of inertia about the centre: m r^2 / 2 for a disc (per metre of thickness), 2/5 m r^2 for a
/// sphere.
template <int Dim>
constexpr double grain_inertia(double mass, double radius) noexcept {
    return (Dim == 2 ? 0.5 : 0.4) * mass * radius * radius;
}

/// Grains with translation and rotation (first seed paper eq. 1). Fields (names as written to output):
/// `id` (persistent, survives sorting and removal), `position`, `velocity`, `angular_velocity` (a scalar
/// w_z in 2D, a vector in 3D), `force`, `torque` (accumulators, cleared at the start of each step's
/// force stage), `radius`, `mass`, `inertia`, `material` (index into the system's material table),
/// `collisions` (how many times the grain began to touch other grains; a deflected grain of Fig. 14) and
/// `grain_contact` (1 while it touches one: set by the contact pass, kept to see the next one begin).
template <int Dim>
class GrainSet : public particles::ParticleSet<Dim> {
public:
    using Vec = core::Vec<Dim>;
    using SpinT = Spin<Dim>;
    using particles::ParticleSet<Dim>::size;
    using particles::ParticleSet<Dim>::id;
    using particles::ParticleSet<Dim>::position;

    /// Registers the fields every grain has, in the order snapshots and checkpoints list them.
    GrainSet() {
        fields_.template add<domain::ParticleId>("id", -1, true);
        fields_.template add<Vec>("position", Vec::zero(), false);
        velocity_ = &fields_.template add<Vec>("velocity", Vec::zero(), true);
        angular_velocity_ = &fields_.template add<SpinT>("angular_velocity", zero_spin<Dim>(), true);
        force_ = &fields_.template add<Vec>("force", Vec::zero(), true);
        torque_ = &fields_.template add<SpinT>("torque", zero_spin<Dim>(), false);
        radius_ = &fields_.template add<double>("radius", 0.0, true);
        mass_ = &fields_.template add<double>("mass", 0.0, true);
        inertia_ = &fields_.template add<double>("inertia", 0.0, false);
        material_ = &fields_.template add<std::int32_t>("material", 0, true);
        collisions_ = &fields_.template add<std::int32_t>("collisions", 0, true);
        grain_contact_ = &fields_.template add<std::int32_t>("grain_contact", 0, false);
        this->bind();
    }

    GrainSet(const GrainSet& o) : particles::ParticleSet<Dim>(o) { rebind(); }
    GrainSet& operator=(const GrainSet& o) {
        particles::ParticleSet<Dim>::operator=(o);
        rebind();
        return *this;
    }

    /// Appends one grain of `material` (density from it) with the id its source gave it (by origin,
    /// domain/particle_id.hpp), at rest unless v is given; returns its index.
    Index add(domain::ParticleId grain_id, const Vec& x, double radius, const GrainMaterial& material,
              std::int32_t material_index, const Vec& v = Vec::zero()) {
        const Index i = size();
        fields_.resize(i + 1);
        id()[i] = grain_id;
        position()[i] = x;
        (*velocity_)[i] = v;
        (*radius_)[i] = radius;
        (*mass_)[i] = grain_mass<Dim>(material.density, radius);
        (*inertia_)[i] = grain_inertia<Dim>((*mass_)[i], radius);
        (*material_)[i] = material_index;
        return i;
    }
    /// Appends one grain to a set built by hand (tests, tools), numbered in the order of adding.
    Index add(const Vec& x, double radius, const GrainMaterial& material, std::int32_t material_index,
              const Vec& v = Vec::zero()) {
        return add(this->take_hand_built_id(), x, radius, material, material_index, v);
    }
    using particles::ParticleSet<Dim>::take_hand_built_id;  // DemSystem's hand-built grains
    /// Reorders and/or removes grains: new[i] = old[source[i]].
    void gather(const std::vector<Index>& source) { fields_.gather(source); }

    Vec* velocity() noexcept { return velocity_->data(); }
    SpinT* angular_velocity() noexcept { return angular_velocity_->data(); }
    Vec* force() noexcept { return force_->data(); }
    SpinT* torque() noexcept { return torque_->data(); }
    double* radius() noexcept { return radius_->data(); }
    double* mass() noexcept { return mass_->data(); }
    double* inertia() noexcept { return inertia_->data(); }
    std::int32_t* material() noexcept { return material_->data(); }
    std::int32_t* collisions() noexcept { return collisions_->data(); }
    std::int32_t* grain_contact() noexcept { return grain_contact_->data(); }

    const Vec* velocity() const noexcept { return velocity_->data(); }
    const SpinT* angular_velocity() const noexcept { return angular_velocity_->data(); }
    const Vec* force() const noexcept { return force_->data(); }
    const SpinT* torque() const noexcept { return torque_->data(); }
    const double* radius() const noexcept { return radius_->data(); }
    const double* mass() const noexcept { return mass_->data(); }
    const double* inertia() const noexcept { return inertia_->data(); }
    const std::int32_t* material() const noexcept { return material_->data(); }
    const std::int32_t* collisions() const noexcept { return collisions_->data(); }
    const std::int32_t* grain_contact() const noexcept { return grain_contact_->data(); }

    /// Points and every output field (grains/*.vtu).
    io::PointCloud snapshot() const { return this->point_cloud(); }

private:
    void rebind() {
        velocity_ = &fields_.template get<Vec>("velocity");
        angular_velocity_ = &fields_.template get<SpinT>("angular_velocity");
        force_ = &fields_.template get<Vec>("force");
        torque_ = &fields_.template get<SpinT>("torque");
        radius_ = &fields_.template get<double>("radius");
        mass_ = &fields_.template get<double>("mass");
        inertia_ = &fields_.template get<double>("inertia");
        material_ = &fields_.template get<std::int32_t>("material");
        collisions_ = &fields_.template get<std::int32_t>("collisions");
        grain_contact_ = &fields_.template get<std::int32_t>("grain_contact");
    }

    using particles::ParticleSet<Dim>::fields_;
    particles::Field<Vec>* velocity_;
    particles::Field<SpinT>* angular_velocity_;
    particles::Field<Vec>* force_;
    particles::Field<SpinT>* torque_;
    particles::Field<double>* radius_;
    particles::Field<double>* mass_;
    particles::Field<double>* inertia_;
    particles::Field<std::int32_t>* material_;
    particles::Field<std::int32_t>* collisions_;
    particles::Field<std::int32_t>* grain_contact_;
};

/// The `fixed` flags of the grains (1: held in place, [[grains]].fixed), or null when no grain is fixed
/// (the field is registered only by cases with fixed grains, so other cases' outputs do not change).
template <int Dim>
const std::int32_t* fixed_flags(const GrainSet<Dim>& grains) {
    return grains.fields().has("fixed") ? grains.fields().template get<std::int32_t>("fixed").data() : nullptr;
}

}  // namespace grit::dem
