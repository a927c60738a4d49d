// grit._grit: the C++ side of the Python module (pybind11). It links grit_core, the library the CLI is built
// from, so a case run here gives the CLI's results bit for bit. The Python package (python/grit/) wraps it in
// the documented API; what is here is its plumbing.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/simulation.hpp"
#include "grit/sim/version.hpp"
#include "simulation_handle.hpp"

namespace py = pybind11;
using namespace grit;

namespace {

python::CaseSource source_of(const std::string& file, const py::object& text, const std::vector<std::string>& overrides) {
    python::CaseSource s;
    s.file = file;
    s.from_text = !text.is_none();
    if (s.from_text) s.text = text.cast<std::string>();
    s.overrides = overrides;
    return s;
}

/// A copy of `values` as an array of `rows` x `components` (or `rows` when components is 1).
template <class T>
py::array_t<T> to_array(const std::vector<T>& values, std::size_t rows, int components) {
    std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(rows)};
    if (components > 1) shape.push_back(components);
    py::array_t<T> a(shape);
    if (!values.empty()) std::memcpy(a.mutable_data(), values.data(), values.size() * sizeof(T));
    return a;
}

/// `values` (`components` per row) with only the first `keep` of each row.
template <class T>
std::vector<T> leading(const std::vector<T>& values, int components, int keep) {
    std::vector<T> out;
    const auto c = static_cast<std::size_t>(components);
    for (std::size_t i = 0; i < values.size(); i += c) out.insert(out.end(), values.begin() + i, values.begin() + i + keep);
    return out;
}

py::dict arrays_of(const python::PhaseArrays& p) {
    py::dict d;
    const std::size_t n = p.size();
    d["position"] = to_array(p.position, n, p.dimension);
    for (const auto& a : p.arrays) {
        // Snapshots write a 2D case's vectors with a third component (VTK's); the arrays keep two.
        const bool planar_vector = p.dimension == 2 && a.components == 3;
        const int c = planar_vector ? 2 : a.components;
        auto put = [&](const auto& values) {
            d[py::str(a.name)] = to_array(planar_vector ? leading(values, 3, 2) : values, n, c);
        };
        if (a.is_int64)
            put(a.integer64);
        else if (a.is_integer)
            put(a.integer);
        else
            put(a.real);
    }
    return d;
}

py::dict values_of(const std::vector<sim::OutputValue>& values) {
    py::dict d;
    for (const auto& v : values) {
        const py::str key(v.group.empty() ? v.name : v.group + "." + v.name);
        if (v.integer)
            d[key] = py::int_(static_cast<long long>(v.value));
        else
            d[key] = py::float_(v.value);
    }
    return d;
}

py::dict summary_of(const sim::RunSummary& s) {
    py::dict d;
    d["status"] = s.status;
    d["particles"] = s.particles;
    d["steps"] = s.steps;
    d["end_time"] = s.end_time;
    d["wall_time_s"] = s.wall_time_s;
    d["particle_steps_per_second"] = s.particle_steps_per_second;
    d["values"] = values_of(s.values);
    d["message"] = s.message;
    return d;
}

}  // namespace

PYBIND11_MODULE(_grit, m) {
    m.doc() = "grit's C++ core (use the grit package, not this module)";
    m.attr("version") = sim::version;
    m.attr("git_revision") = sim::git_revision();

    // InputError (a case or option refused: key, value, reason) becomes grit.CaseError; a blow-up
    // grit.BlowUp; a run stopped by SIGINT KeyboardInterrupt (its checkpoint written first).
    static py::exception<core::InputError> case_error(m, "CaseError", PyExc_ValueError);
    static py::exception<core::BlowUpError> blow_up(m, "BlowUp", PyExc_RuntimeError);
    static py::exception<sim::Interrupted> interrupted(m, "Interrupted", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const core::InputError& e) {
            case_error(e.what());
        } catch (const core::BlowUpError& e) {
            blow_up(e.what());
        } catch (const sim::Interrupted& e) {
            if (e.signal() == 2)
                PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
            else
                interrupted(e.what());
        }
    });

    m.def(
        "check_case",
        [](const std::string& file, const py::object& text, const std::vector<std::string>& overrides, bool build) {
            const auto spec = python::read_case(source_of(file, text, overrides));
            py::dict d;
            d["name"] = spec.name;
            d["title"] = spec.title;
            d["dimension"] = spec.dimension;
            d["end_time"] = spec.end_time;
            d["output_interval"] = spec.output_interval;
            if (build) {  // as `grit check`: the particles built and the first step's rates computed
                python::SimulationHandle s(spec);
                d["estimate"] = s.estimate();
            }
            return d;
        },
        py::arg("file"), py::arg("text"), py::arg("overrides"), py::arg("build"));

    m.def("set_threads", [](int n) { parallel::set_threads(n); });
    m.def("max_threads", [] { return parallel::max_threads(); });

    m.def(
        "run",
        [](const std::string& file, const py::object& text, const std::vector<std::string>& overrides,
           const py::object& out, bool quiet, bool overwrite, const py::object& progress) {
            const auto spec = python::read_case(source_of(file, text, overrides));
            const bool write = !out.is_none();
            const std::filesystem::path folder = write ? out.cast<std::filesystem::path>() : std::filesystem::path();
            // The callback is copied where the GIL is released (into the run's options): the copies share one
            // reference to it, which this function, holding the GIL, outlives.
            std::function<void(double, long)> on_output;
            if (!progress.is_none()) {
                auto callback = std::make_shared<py::object>(progress);
                on_output = [callback](double time, long step) {
                    py::gil_scoped_acquire gil;  // the run released it
                    (*callback)(time, step);
                };
            }
            sim::RunSummary summary;
            {
                py::gil_scoped_release release;  // a notebook stays responsive while the C++ runs
                summary = python::run_case(spec, folder, write, quiet, overwrite, on_output);
            }
            return summary_of(summary);
        },
        py::arg("file"), py::arg("text"), py::arg("overrides"), py::arg("out"), py::arg("quiet"),
        py::arg("overwrite"), py::arg("progress"));

    m.def(
        "restart",
        [](const std::string& folder, const py::object& file, const py::object& text,
           const std::vector<std::string>& overrides, double end_time, bool quiet) {
            python::CaseSource source;
            if (!file.is_none()) source = source_of(file.cast<std::string>(), text, overrides);
            sim::RunSummary summary;
            {
                py::gil_scoped_release release;
                summary = python::restart_run(folder, file.is_none() ? nullptr : &source, end_time, quiet);
            }
            return summary_of(summary);
        },
        py::arg("folder"), py::arg("file"), py::arg("text"), py::arg("overrides"), py::arg("end_time"),
        py::arg("quiet"));

    py::class_<python::SimulationHandle>(m, "SimulationHandle")
        .def(py::init([](const std::string& file, const py::object& text, const std::vector<std::string>& overrides,
                         const std::string& checkpoint) {
                 return std::make_unique<python::SimulationHandle>(python::read_case(source_of(file, text, overrides)),
                                                                   checkpoint);
             }),
             py::arg("file"), py::arg("text"), py::arg("overrides"), py::arg("checkpoint"))
        .def_property_readonly("dimension", &python::SimulationHandle::dimension)
        .def_property_readonly("time", &python::SimulationHandle::time)
        .def_property_readonly("step", &python::SimulationHandle::step)
        .def_property_readonly("dt", &python::SimulationHandle::time_step)
        .def(
            "advance",
            [](python::SimulationHandle& s, double time) {
                // Ctrl-C: Python's handler only flags the signal; look at the flag every 0.2 s of wall time
                // (with the GIL: a few microseconds), and stop after the step with KeyboardInterrupt.
                auto last = std::chrono::steady_clock::now();
                auto poll = [&last] {
                    const auto now = std::chrono::steady_clock::now();
                    if (now - last < std::chrono::milliseconds(200)) return;
                    last = now;
                    py::gil_scoped_acquire gil;
                    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                };
                py::gil_scoped_release release;
                s.advance(time, poll);
            },
            py::arg("time"))
        .def("fields", [](const python::SimulationHandle& s, const std::string& phase) { return arrays_of(s.fields(phase)); })
        .def("outputs", [](const python::SimulationHandle& s) { return values_of(s.outputs()); })
        .def("checkpoint", &python::SimulationHandle::checkpoint, py::arg("file"));
}
