// Mesh walls module: set-up, impact and wear booking, wear maps.
#include "grit/modules/mesh_wear.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "grit/core/error.hpp"
#include "grit/dem/plane_wall.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/mesh/mirror_partners.hpp"
#include "grit/modules/grains.hpp"
#include "grit/wear/wear_models.hpp"

namespace grit::modules {

template <int Dim>
MeshWearModule<Dim>::MeshWearModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup) {
    if constexpr (Dim != 3) {
        throw core::InputError("key 'mesh': mesh walls need a 3D case (simulation.dimension = 3)");
    } else {
        std::size_t triangles = 0;
        for (const auto& m : setup.spec.meshes) {
            dem::MeshWall wall;
            wall.name = m.name;
            wall.mesh = *m.mesh;
            wall.material = m.material;
            wall.motion.velocity = core::to_vec<3>(m.velocity);
            wall.motion.angular_velocity = core::to_vec<3>(m.angular_velocity);
            wall.motion.centre = core::to_vec<3>(m.centre);
            first_triangle_.push_back(triangles);
            triangles += m.mesh->triangle_count();
            state.grains->add_mesh(std::move(wall));
        }
        first_triangle_.push_back(triangles);
        map_ = wear::WearMap(triangles);
        if (setup.spec.symmetry_plane) {
            lone_ = wear::WearMap(triangles);
            pair_mirror_images();
        }
    }
}

template <int Dim>
void MeshWearModule<Dim>::pair_mirror_images() {
    if constexpr (Dim == 3) {
        const auto& meshes = setup_.spec.meshes;
        const std::string& plane = setup_.spec.symmetry_key;
        for (const auto& m : meshes) {
            // The mirror image of a mesh moving at v moves at v with v_x negated, and of one turning at w turns
            // at (w_x, -w_y, -w_z) (an axial vector): its motion is its own only along y and z, and turning
            // about an axis along x (which the mirror maps onto itself).
            const bool along_plane = m.velocity.empty() || m.velocity[0] == 0.0;
            const bool about_x = m.angular_velocity.empty() ||
                                 (m.angular_velocity[1] == 0.0 && m.angular_velocity[2] == 0.0);
            if (!along_plane || !about_x)
                throw core::InputError(fmt::format(
                    "key '{}': mesh '{}' moves across the symmetry plane of {} (its mirror image would move "
                    "otherwise); with a symmetry plane a mesh may move along y and z and turn about an axis along "
                    "x only",
                    m.key, m.name, plane));
        }
        const auto& corners = state_.grains->meshes()->corners();
        const double tolerance = mesh::mirror_tolerance(corners);
        mirror_ = mesh::mirror_partners(corners, 0, tolerance);
        for (std::size_t t = 0; t < corners.size(); ++t) {
            if (mirror_[t] >= 0) continue;
            const auto& c = corners[t];
            if (c[0][0] >= -tolerance && c[1][0] >= -tolerance && c[2][0] >= -tolerance) continue;
            const auto [m, local] = state_.grains->meshes()->locate(static_cast<std::int32_t>(t));
            const auto centre = (c[0] + c[1] + c[2]) * (1.0 / 3.0);
            throw core::InputError(fmt::format(
                "key '{}': mesh '{}' ({}) is not symmetric about the plane x = 0 of {}: its triangle {} at "
                "({:.6g}, {:.6g}, {:.6g}) m has no mirror image in the meshes; give the meshes whole and "
                "symmetric, or only their x >= 0 part",
                meshes[m].key, meshes[m].name, meshes[m].file.string(), plane, local, centre[0], centre[1],
                centre[2]));
        }
    }
}

template <int Dim>
wear::WearMap MeshWearModule<Dim>::wear_map() const {
    if (mirror_.empty()) return map_;
    wear::WearMap whole = lone_;
    for (std::size_t t = 0; t < map_.size(); ++t) {
        whole.add_from(map_, t, t);
        if (mirror_[t] >= 0) whole.add_from(map_, static_cast<std::size_t>(mirror_[t]), t);
    }
    return whole;
}

template <int Dim>
void MeshWearModule<Dim>::install(sim::Pipeline& pipeline) {
    // After the grains' forces, which found this step's mesh contacts at the new positions.
    pipeline.add(sim::Hook::grain_force, "mesh_wear", [this] { book(); });
}

template <int Dim>
void MeshWearModule<Dim>::book() {
    if constexpr (Dim == 3) {
        const auto& system = *state_.grains;
        const dem::MeshWalls& walls = *system.meshes();
        const auto& grains = system.grains();
        const double time = state_.clock.time + state_.clock.dt, dt = state_.clock.dt;
        const auto& meshes = setup_.spec.meshes;
        const auto& fields = grains.fields();
        const std::int32_t* straddling =
            mirror_.empty() ? nullptr : fields.template get<std::int32_t>(dem::straddling_field).data();
        for (Index i = 0; i < grains.size(); ++i) {
            // A grain with a mirror twin books into map_, whose triangles count their mirror images' too.
            wear::WearMap& map = straddling && straddling[i] > 0 ? lone_ : map_;
            const dem::MeshContact* contacts = walls.contacts_of(i);
            for (int c = 0; c < walls.contact_count(i); ++c) {
                const dem::MeshContact& k = contacts[c];
                const auto t = static_cast<std::size_t>(k.triangle);
                const auto& spec = meshes[walls.locate(k.triangle).first];
                const double speed = core::norm(k.relative_velocity);
                const double angle = impact_angle<3>(k.relative_velocity, k.normal);  // [deg]
                const double radians = angle * std::numbers::pi / 180.0;
                const auto& material = system.materials()[static_cast<std::size_t>(grains.material()[i])];
                const wear::Impactor grain{grains.mass()[i], grains.radius()[i], material.density,
                                           material.youngs_modulus_for_wear(), material.poisson_ratio};
                if (k.fresh) {
                    state_.impacts.add({time, grains.id()[i], spec.name, speed, angle,
                                        core::to_array3(grains.position()[i]), grains.collisions()[i]});
                    map.add_impact(t, angle, speed);
                    map.add_mass(t,
                                  spec.wear_material.density *
                                      wear::impact_volume(spec.wear_model, spec.wear_material, grain, speed, radians));
                }
                // LIGGGHTS' form counts while the grain closes in on the wall.
                if (spec.wear_model == wear::WearModel::finnie_liggghts &&
                    core::dot(k.relative_velocity, k.normal) > 0.0)
                    map.add_mass(t, wear::liggghts_mass_rate(spec.wear_material, speed, k.force, radians) * dt);
            }
        }
    }
}

template <int Dim>
void MeshWearModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const wear::WearMap map = wear_map();
    out.push_back(sim::OutputValue::real("wear_mass_total", map.total_mass(0, map.size()), domain::Combine::sum));
    const auto& meshes = setup_.spec.meshes;
    for (std::size_t m = 0; m < meshes.size(); ++m)
        out.push_back(sim::OutputValue::real("wear_mass_" + meshes[m].name,
                                             map.total_mass(first_triangle_[m], first_triangle_[m + 1]), domain::Combine::sum));
}

template <int Dim>
void MeshWearModule<Dim>::open_output(const sim::OutputPlace& place, bool restart) {
    namespace fs = std::filesystem;
    fs::create_directories(place.dir / "walls");
    if (!restart)
        for (const auto& e : fs::directory_iterator(place.dir / "walls"))
            if (e.path().extension() == ".vtu") fs::remove(e.path());
    pvd_ = std::make_unique<io::PvdWriter>(place.dir / (place.name + "_walls.pvd"));
    if (restart) pvd_->restore(restored_pvd_);
}

template <int Dim>
void MeshWearModule<Dim>::write_output(const sim::OutputPlace& place) {
    if constexpr (Dim == 3) {
        if (!place.snapshots) return;
        const dem::MeshWalls& walls = *state_.grains->meshes();
        const auto& corners = walls.corners();
        const auto& meshes = setup_.spec.meshes;
        io::TriangleSurface s;
        // Three points per triangle (the corners where they are now): cell data need no shared points.
        for (std::size_t t = 0; t < corners.size(); ++t)
            for (std::size_t c = 0; c < 3; ++c) {
                for (int k = 0; k < 3; ++k)
                    s.points.push_back(corners[t][c][k]);
                s.triangles.push_back(static_cast<std::int64_t>(3 * t + c));
            }
        auto mass = io::PointArray::reals("wear_mass", 1), depth = io::PointArray::reals("wear_depth", 1),
             count = io::PointArray::integers("impact_count", 1), angle = io::PointArray::reals("mean_impact_angle", 1),
             speed = io::PointArray::reals("mean_impact_speed", 1), which = io::PointArray::integers("mesh", 1);
        const wear::WearMap map = wear_map();
        for (std::size_t t = 0; t < corners.size(); ++t) {
            const auto [m, local] = walls.locate(static_cast<std::int32_t>(t));
            const double rho = meshes[m].wear_material.density;
            mass.real.push_back(map.mass(t));
            depth.real.push_back(std::isfinite(rho) ? map.mass(t) / (rho * meshes[m].mesh->area(local)) : 0.0);
            count.integer.push_back(static_cast<std::int32_t>(map.impacts(t)));
            angle.real.push_back(map.mean_angle(t));
            speed.real.push_back(map.mean_speed(t));
            which.integer.push_back(static_cast<std::int32_t>(m));
        }
        s.cell_arrays = {mass, depth, count, angle, speed, which};
        io::NameList names{"mesh_names", {}};
        for (const auto& m : meshes)
            names.values.push_back(m.name);
        s.names.push_back(std::move(names));
        const auto file = fmt::format("walls/{}_walls_{:06}.vtu", place.name, snapshot_index_++);
        io::write_surface_vtu(place.dir / file, s);
        pvd_->add(state_.clock.time, file);
    }
}

template <int Dim>
void MeshWearModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("snapshot_index", static_cast<std::int64_t>(snapshot_index_));
    auto map = group.create_group("wear_map");
    map_.save(map);
    if (!mirror_.empty()) {
        auto lone = group.create_group("wear_map_straddling");
        lone_.save(lone);
    }
    io::save_pvd_entries(group, "pvd", pvd_ ? pvd_->entries() : restored_pvd_);
}

template <int Dim>
void MeshWearModule<Dim>::load(const io::Hdf5Group& group) {
    snapshot_index_ = static_cast<long>(group.read_int("snapshot_index"));
    map_.load(group.open_group("wear_map"));
    if (!mirror_.empty()) lone_.load(group.open_group("wear_map_straddling"));
    restored_pvd_ = io::load_pvd_entries(group, "pvd");
}

template class MeshWearModule<2>;
template class MeshWearModule<3>;

}  // namespace grit::modules
