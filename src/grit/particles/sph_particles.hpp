// The SPH particle set: fluid, solid and wall particles in one structure of arrays, so that they meet in
// the same neighbour loops (fluid-solid interaction is SPH interaction, first seed paper section 2).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/particles/field_registry.hpp"
#include "grit/particles/particle_set.hpp"

namespace grit::particles {

template <int Dim>
class SphParticles : public ParticleSet<Dim> {
public:
    using Vec = core::Vec<Dim>;
    using ParticleSet<Dim>::size;
    using ParticleSet<Dim>::id;
    using ParticleSet<Dim>::position;

    /// Registers the fields every SPH particle has, in the order snapshots and checkpoints list them.
    SphParticles() {
        fields_.template add<Vec>("position", Vec::zero(), false);
        velocity_ = &fields_.template add<Vec>("velocity", Vec::zero(), true);
        velocity_half_ = &fields_.template add<Vec>("velocity_half", Vec::zero(), false);
        acceleration_ = &fields_.template add<Vec>("acceleration", Vec::zero(), false);
        density_ = &fields_.template add<double>("density", 0.0, true);
        density_half_ = &fields_.template add<double>("density_half", 0.0, false);
        density_rate_ = &fields_.template add<double>("density_rate", 0.0, false);
        pressure_ = &fields_.template add<double>("pressure", 0.0, true);
        mass_ = &fields_.template add<double>("mass", 0.0, true);
        phase_ = &fields_.template add<std::int32_t>("phase", 0, true);
        material_ = &fields_.template add<std::int32_t>("material", 0, true);
        fields_.template add<domain::ParticleId>("id", -1, true);
        this->bind();
    }

    SphParticles(const SphParticles& o) : ParticleSet<Dim>(o), generation_(o.generation_), removal_(o.removal_) {
        rebind();
    }
    SphParticles& operator=(const SphParticles& o) {
        ParticleSet<Dim>::operator=(o);
        generation_ = o.generation_;
        removal_ = o.removal_;
        rebind();
        return *this;
    }

    /// Grows the set by n particles made by `source` with serials first_serial, first_serial + 1, ...
    /// (their ids by origin, domain/particle_id.hpp; fields take their fill values) and returns the first
    /// new index.
    Index append(Index n, domain::IdSource source, std::int64_t first_serial) {
        std::vector<std::int64_t> serials(static_cast<std::size_t>(n));
        for (Index k = 0; k < n; ++k) serials[static_cast<std::size_t>(k)] = first_serial + k;
        return append(source, serials);
    }
    /// Grows the set by one particle per serial, made by `source` (a part of a block: the serials of the
    /// lattice points kept), and returns the first new index.
    Index append(domain::IdSource source, const std::vector<std::int64_t>& serials) {
        const Index first = size();
        std::vector<domain::ParticleId> ids(serials.size());
        for (std::size_t k = 0; k < serials.size(); ++k) ids[k] = domain::make_particle_id(source, serials[k]);
        fields_.resize(first + static_cast<Index>(serials.size()));
        std::copy(ids.begin(), ids.end(), id() + first);
        ++generation_;
        return first;
    }
    /// Grows a set built by hand (tests, tools) by n particles, numbered in the order of appending.
    Index append(Index n) { return append(n, {domain::IdKind::hand_built, 0}, this->take_hand_built_serials(n)); }
    /// Grows the set by n mirror images (a symmetry plane's ghosts, modules/symmetry_plane.*): they take
    /// no identifier of their own; the caller gives each the id image_id(source id) and its source's values.
    Index append_images(Index n) { return append_received(n); }
    /// Grows the set by n particles whose every field, the id included, the caller fills: mirror images,
    /// ghosts of another sub-domain's particles, and particles that migrate here from one
    /// (domain/process_halo.hpp).
    Index append_received(Index n) {
        const Index first = size();
        fields_.resize(first + n);
        ++generation_;
        return first;
    }
    /// The id of the mirror image of the particle with id `source` (negative, so every module can tell an
    /// image from a particle: images are not removed, counted or written for themselves).
    static constexpr domain::ParticleId image_id(domain::ParticleId source) noexcept { return -2 - source; }
    static constexpr domain::ParticleId image_source(domain::ParticleId image) noexcept { return -2 - image; }
    static constexpr bool is_image_id(domain::ParticleId id) noexcept { return id <= -2; }
    bool is_image(Index i) const noexcept { return is_image_id(id()[i]); }
    /// How many images the set holds.
    Index image_count() const noexcept {
        Index n = 0;
        for (Index i = 0; i < size(); ++i) n += is_image(i);
        return n;
    }
    /// Starts new particle i (from append) at position x, velocity v and density rho, with mass m, phase
    /// and material; the half-step velocity and density start equal to v and rho.
    void start(Index i, const Vec& x, const Vec& v, double rho, double m, Phase phase, std::int32_t material) {
        position()[i] = x;
        (*velocity_)[i] = v;
        (*velocity_half_)[i] = v;
        (*density_)[i] = rho;
        (*density_half_)[i] = rho;
        (*mass_)[i] = m;
        (*phase_)[i] = static_cast<std::int32_t>(phase);
        (*material_)[i] = material;
    }
    /// Reorders and/or removes particles: new[i] = old[source[i]].
    void gather(const std::vector<Index>& source) {
        fields_.gather(source);
        ++generation_;
    }
    /// Removes particles: new[i] = old[keep[i]], keep ascending. Unlike gather(), the set remembers what
    /// it kept since the last other change, so that data built for an earlier generation (neighbour
    /// lists) can be compacted instead of rebuilt (kept_since).
    void remove(const std::vector<Index>& keep) {
        const std::uint64_t before = generation_;
        gather(keep);
        if (removal_.to == before) {  // removals in a row compose: keep indices of the earlier set
            std::vector<Index> composed(keep.size());
            for (std::size_t i = 0; i < keep.size(); ++i) composed[i] = removal_.keep[static_cast<std::size_t>(keep[i])];
            removal_.keep = std::move(composed);
        } else {
            removal_.from = before;
            removal_.keep = keep;
        }
        removal_.to = generation_;
    }
    /// When the only changes since `generation` were removals: the indices, in that generation's set,
    /// of the particles kept (new[i] = then[(*result)[i]]); otherwise null.
    const std::vector<Index>* kept_since(std::uint64_t generation) const noexcept {
        return removal_.from == generation && removal_.to == generation_ ? &removal_.keep : nullptr;
    }
    /// Changes each time particles are added, removed or reordered: per-particle data kept outside the
    /// registry (neighbour lists, per-step scratch) records it and is valid while it is unchanged.
    std::uint64_t generation() const noexcept { return generation_; }
    /// Reads back what save() wrote (a new generation); the set must have the same fields registered.
    void load(const io::Hdf5Group& group) {
        ParticleSet<Dim>::load(group);
        ++generation_;
    }

    Vec* velocity() noexcept { return velocity_->data(); }
    Vec* acceleration() noexcept { return acceleration_->data(); }
    /// Leap-frog state: velocity and density at the half step t + dt/2 (velocity() and density()
    /// hold the values at t that the SPH sums read).
    Vec* velocity_half() noexcept { return velocity_half_->data(); }
    double* density_half() noexcept { return density_half_->data(); }
    double* density() noexcept { return density_->data(); }
    double* density_rate() noexcept { return density_rate_->data(); }
    double* pressure() noexcept { return pressure_->data(); }
    double* mass() noexcept { return mass_->data(); }
    std::int32_t* phase() noexcept { return phase_->data(); }
    std::int32_t* material() noexcept { return material_->data(); }

    const Vec* velocity() const noexcept { return velocity_->data(); }
    const double* density() const noexcept { return density_->data(); }
    const double* pressure() const noexcept { return pressure_->data(); }
    const double* mass() const noexcept { return mass_->data(); }
    const std::int32_t* phase() const noexcept { return phase_->data(); }
    const std::int32_t* material() const noexcept { return material_->data(); }

    /// Points and every output field, ready for a snapshot writer; a field is NaN where its output scope
    /// excludes the particle's phase and material (FieldBase::set_output_scope). Images are left out.
    io::PointCloud snapshot() const {
        if (image_count() > 0) {
            SphParticles copy(*this);
            std::vector<Index> keep;
            for (Index i = 0; i < size(); ++i)
                if (!is_image(i)) keep.push_back(i);
            copy.gather(keep);
            return copy.snapshot();
        }
        return this->point_cloud(phase(), material());
    }

private:
    void rebind() {
        velocity_ = &fields_.template get<Vec>("velocity");
        velocity_half_ = &fields_.template get<Vec>("velocity_half");
        acceleration_ = &fields_.template get<Vec>("acceleration");
        density_ = &fields_.template get<double>("density");
        density_half_ = &fields_.template get<double>("density_half");
        density_rate_ = &fields_.template get<double>("density_rate");
        pressure_ = &fields_.template get<double>("pressure");
        mass_ = &fields_.template get<double>("mass");
        phase_ = &fields_.template get<std::int32_t>("phase");
        material_ = &fields_.template get<std::int32_t>("material");
    }

    using ParticleSet<Dim>::fields_;
    Field<Vec>* velocity_;
    Field<Vec>* velocity_half_;
    Field<Vec>* acceleration_;
    Field<double>* density_;
    Field<double>* density_half_;
    Field<double>* density_rate_;
    Field<double>* pressure_;
    Field<double>* mass_;
    Field<std::int32_t>* phase_;
    Field<std::int32_t>* material_;
    std::uint64_t generation_ = 0;
    // The removals since generation `from`, up to `to` (the current one while nothing else changed).
    struct Removal {
        std::uint64_t from = ~std::uint64_t{0}, to = ~std::uint64_t{0};
        std::vector<Index> keep;
    } removal_;
};

}  // namespace grit::particles
