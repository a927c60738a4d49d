// What every particle set shares, the SPH particles and the DEM grains alike: one registry of fields
// (sorted, removed, grown, saved and written together), the persistent ids by origin and the positions,
// the ids of sets built by hand, checkpointing, and the snapshot writer's points and arrays. The two sets
// add their own fields and rules (SphParticles: phases, generations, mirror images; GrainSet: radii,
// spins) on this base, so that the two do not drift apart.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/io/point_data.hpp"
#include "grit/particles/field_registry.hpp"

namespace grit::particles {

template <int Dim>
class ParticleSet {
public:
    using Vec = core::Vec<Dim>;

    FieldRegistry& fields() noexcept { return fields_; }
    const FieldRegistry& fields() const noexcept { return fields_; }
    Index size() const noexcept { return fields_.size(); }

    /// A particle's id by origin (domain/particle_id.hpp): unique, kept through sorting, removal and (over
    /// many processes) migration, for tracking particles and finding them again.
    domain::ParticleId* id() noexcept { return id_->data(); }
    const domain::ParticleId* id() const noexcept { return id_->data(); }
    Vec* position() noexcept { return position_->data(); }
    const Vec* position() const noexcept { return position_->data(); }

    /// Every saved field into `group` (a checkpoint's particle set; ids come from their sources, which
    /// keep their own counters).
    void save(io::Hdf5Group& group) const { fields_.save(group); }
    /// Reads back what save() wrote; the set must have the same fields registered.
    void load(const io::Hdf5Group& group) { fields_.load(group); }

protected:
    ParticleSet() = default;
    ParticleSet(const ParticleSet& o) : fields_(o.fields_), next_hand_built_(o.next_hand_built_) { bind(); }
    ParticleSet& operator=(const ParticleSet& o) {
        fields_ = o.fields_;
        next_hand_built_ = o.next_hand_built_;
        bind();
        return *this;
    }

    /// Finds the `id` and `position` fields, which the set registers in its own order (the order of the
    /// snapshot's arrays and the checkpoint's datasets); call after registering them and after a copy.
    void bind() {
        id_ = &fields_.template get<domain::ParticleId>("id");
        position_ = &fields_.template get<Vec>("position");
    }

    /// The next id of a set built by hand (tests, tools): numbered in the order of adding.
    domain::ParticleId take_hand_built_id() {
        return domain::make_particle_id({domain::IdKind::hand_built, 0}, next_hand_built_++);
    }
    std::int64_t take_hand_built_serials(Index n) {
        const std::int64_t first = next_hand_built_;
        next_hand_built_ += n;
        return first;
    }

    /// Points (always three coordinates) and every output field, ready for a snapshot writer; with `phase`
    /// and `material`, a field is NaN where its output scope excludes the particle's phase and material.
    io::PointCloud point_cloud(const std::int32_t* phase = nullptr, const std::int32_t* material = nullptr) const {
        io::PointCloud cloud;
        cloud.points.assign(static_cast<std::size_t>(size()) * 3, 0.0);
        const Vec* x = position();
        for (Index i = 0; i < size(); ++i)
            for (int k = 0; k < Dim; ++k) cloud.points[3 * static_cast<std::size_t>(i) + k] = x[i][k];
        fields_.append_output(cloud, phase, material);
        return cloud;
    }

    FieldRegistry fields_;

private:
    Field<domain::ParticleId>* id_ = nullptr;
    Field<Vec>* position_ = nullptr;
    std::int64_t next_hand_built_ = 0;
};

}  // namespace grit::particles
