// Reading shapes and meshes (shape_reader.hpp).
#include "grit/io/shape_reader.hpp"

#include "grit/mesh/stl_file.hpp"

namespace grit::io {

namespace {
using core::InputError;
}  // namespace

OutletSpec read_box(const Section& s, int dim) {
    OutletSpec o;
    o.key = s.path();
    o.min = s.vector("min", dim, "[m]");
    o.max = s.vector("max", dim, "[m]");
    for (int k = 0; k < dim; ++k)
        if (o.max[k] <= o.min[k]) s.fail("max", "must exceed min in every direction");
    return o;
}

std::shared_ptr<const mesh::TriangleMesh> read_placed_mesh(const Section& s, const std::filesystem::path& folder,
                                                           bool watertight, std::filesystem::path* resolved) {
    const std::filesystem::path file = s.text("file");
    const std::filesystem::path path = file.is_absolute() ? file : folder / file;
    if (resolved) *resolved = path;
    mesh::Placement placement;
    placement.scale = s.number_or("scale", 1.0, positive("[-]"));
    placement.rotate = core::to_vec<3>(s.vector_or("rotate", 3, "[deg]", {0.0, 0.0, 0.0}));
    placement.translate = core::to_vec<3>(s.vector_or("translate", 3, "[m]", {0.0, 0.0, 0.0}));
    return std::make_shared<const mesh::TriangleMesh>(
        mesh::TriangleMesh::from_facets(mesh::read_stl(path), placement, path.string(), watertight));
}

ShapeSpec read_shape(const Section& s, int dim, double dx, bool allow_tank, const std::filesystem::path& folder) {
    ShapeSpec shape;
    std::vector<std::string> kinds = {"box", "disc", "sphere"};
    if (dim == 3) kinds.push_back("cylinder");
    if (allow_tank) kinds.push_back("tank");
    if (allow_tank && dim == 3) kinds.push_back("mesh");
    shape.kind = s.choice("shape", "box", kinds);
    if (shape.kind == "sphere") shape.kind = "disc";
    const char* axis = "xyz";
    if (shape.kind == "mesh") {
        // Wall particles are laid by the signed distance: outside/inside need a closed surface.
        shape.side = s.choice("side", "outside", {"outside", "inside", "front", "back"});
        shape.thin = s.flag_or("thin", false);
        if (shape.thin && shape.side != "front" && shape.side != "back")
            s.fail("thin", fmt::format("a thin wall has water on the side its facets face or on the other, so it needs "
                                       "side = \"front\" or \"back\", not \"{}\"", shape.side));
        shape.mesh = read_placed_mesh(s, folder, shape.side == "outside" || shape.side == "inside");
        shape.layers = s.integer_or("layers", 3, 1, 20);
    } else if (shape.kind == "box" || shape.kind == "tank") {
        shape.min = s.vector("min", dim, "[m]");
        shape.max = s.vector("max", dim, "[m]");
        for (int k = 0; k < dim; ++k) {
            if (shape.max[k] <= shape.min[k])
                s.fail("max", fmt::format("must exceed min in {} ({} <= {})", axis[k], shape.max[k], shape.min[k]));
            if (shape.kind == "box" && shape.max[k] - shape.min[k] < dx)
                s.fail("max", fmt::format("the box is {} m wide in {}, less than numerics.particle_spacing = {} m "
                                          "(lengths are in metres: 0.1 mm is 1e-4)",
                                          shape.max[k] - shape.min[k], axis[k], dx));
        }
        if (shape.kind == "tank") {
            shape.layers = s.integer_or("layers", 3, 1, 20);
            shape.open = s.strings_or("open", {"top"});
            std::vector<std::string> sides = {"left", "right", "bottom", "top"};
            if (dim == 3) sides = {"left", "right", "front", "back", "bottom", "top"};
            for (const auto& o : shape.open)
                if (std::find(sides.begin(), sides.end(), o) == sides.end())
                    s.fail("open", fmt::format("unknown side \"{}\"", o));
        }
    } else if (shape.kind == "cylinder") {
        shape.center = s.vector("center", dim, "[m]");
        shape.radius = s.number("radius", positive("[m]"));
        shape.length = s.number("length", positive("[m]"));
        shape.axis = s.choice("axis", "z", {"x", "y", "z"})[0] - 'x';
        if (2.0 * shape.radius < dx || shape.length < dx)
            s.fail("radius", fmt::format("the cylinder is smaller than numerics.particle_spacing = {} m", dx));
    } else {
        shape.center = s.vector("center", dim, "[m]");
        shape.radius = s.number("radius", positive("[m]"));
        if (2.0 * shape.radius < dx)
            s.fail("radius", fmt::format("the disc is smaller than numerics.particle_spacing = {} m", dx));
    }
    return shape;
}

void read_meshes(const Section& top, CaseSpec& c, GrainMaterialTable& grain_table) {
    const auto sections = top.sections("mesh");
    if (sections.empty()) return;
    if (c.dimension != 3) throw InputError("key 'mesh': mesh walls need a 3D case (simulation.dimension = 3)");
    if (!c.has_grains()) throw InputError("key 'mesh': mesh walls act on grains for now; the case has no [[grains]] or [abrasive]");
    const std::filesystem::path folder = c.source.parent_path();
    for (const Section& m : sections) {
        MeshSpec spec;
        spec.key = m.path();
        spec.name = m.text_or("name", fmt::format("mesh{}", c.meshes.size()));
        if (spec.name.empty() || spec.name.find_first_of(", \t\"") != std::string::npos)
            m.fail("name", "must be a non-empty name without commas, spaces or quotes");
        for (const auto& other : c.meshes)
            if (other.name == spec.name) m.fail("name", "is the name of another [[mesh]]");
        spec.mesh = read_placed_mesh(m, folder, m.flag_or("watertight", false), &spec.file);
        spec.material = m.has("material") ? grain_table.resolve(m, "material", m.text("material")) : c.first_grain_material();
        const std::string model = m.choice("wear_model", "none", {"none", "finnie", "bitter", "oka", "finnie_liggghts"});
        spec.wear_model = *wear::wear_model_named(model);
        if (spec.wear_model != wear::WearModel::none) {
            const std::string material_name = m.has("wear_material") ? m.text("wear_material")
                                                                     : c.grain_materials[static_cast<std::size_t>(spec.material)].name;
            spec.wear_material = read_wear_material(top, m, m.has("wear_material") ? "wear_material" : "material", material_name);
            for (const std::string& k : wear::needed_keys(spec.wear_model)) {
                const auto& w = spec.wear_material;
                const double value = k == "density" ? w.density : k == "youngs_modulus" ? w.youngs_modulus
                                   : k == "poisson_ratio" ? w.poisson_ratio : k == "flow_stress" ? w.flow_stress
                                   : k == "elastic_limit" ? w.elastic_limit : k == "vickers_hardness" ? w.vickers_hardness
                                                                            : w.bitter_deformation_factor;
                if (!std::isfinite(value))
                    throw InputError(fmt::format("key 'wear_materials.{}.{}': needed by {}.wear_model = \"{}\"; give it "
                                                 "(or based_on = a built-in wear material)",
                                                 w.name, k, spec.key, model));
            }
        }
        spec.velocity = m.vector_or("velocity", 3, "[m/s]", {0.0, 0.0, 0.0});
        spec.angular_velocity = m.vector_or("angular_velocity", 3, "[rad/s]", {0.0, 0.0, 0.0});
        spec.centre = m.vector_or("centre", 3, "[m]", {0.0, 0.0, 0.0});
        c.meshes.push_back(std::move(spec));
    }
    // Entries no mesh uses are still checked.
    const Section defined = top.section("wear_materials");
    for (const auto& name : defined.keys()) {
        bool used = false;
        for (const auto& spec : c.meshes) used |= spec.wear_model != wear::WearModel::none && spec.wear_material.name == name;
        if (!used) read_wear_material(top, defined, name, name);
    }
}

}  // namespace grit::io
