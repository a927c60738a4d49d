"""Shared by grit's plot scripts: the words on a plot of a run or a sweep, fit for a report.

A figure's heading names the case (its name and title) and the run's key parameters (the jet's diameter
and velocity or pressure, the abrasive and its mass flow, the specimen's material, the particle spacing,
2D or 3D, and the --set that changed anything else), read from the run's summary.json and from its case
file where that is still the text the run was made with (summary.json's case_digest), with the run's
--set applied to it. Times are written in s, ms or µs and masses in kg, g, mg or µg, whichever fits the
values. Standard library only (tomllib of Python 3.11 where present, else the case file is not read).
"""
import json
import pathlib
import re
import textwrap

try:
    import tomllib
except ImportError:  # Python < 3.11: the heading is made from summary.json and the --set alone
    tomllib = None

MU = "\u00b5"  # micro: "µs", not "us"
BELOW = "below one particle spacing"
SEP = "  \u00b7  "  # between the parameters of a heading  # the legend's words for a crater shallower than the resolution


def load_summary(folder):
    """A run folder's summary.json as a dict ({} without one, or where it cannot be read)."""
    path = pathlib.Path(folder) / "summary.json"
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return {}


# --- units ----------------------------------------------------------------------------------------------

def time_scale(t_end):
    """(scale, unit) for times up to t_end [s]: µs below 1 ms, ms below 1 s, else s."""
    t_end = abs(float(t_end)) if t_end == t_end else 0.0
    if t_end < 1e-3:
        return 1e6, MU + "s"
    if t_end < 1.0:
        return 1e3, "ms"
    return 1.0, "s"


def time_text(t, t_end=None):
    """'20 µs', '100 ms', '1.5 s' (in the unit that fits t_end, by default t itself)."""
    scale, unit = time_scale(t if t_end is None else t_end)
    return f"{float(t) * scale:.3g} {unit}"


def length_text(x):
    """A length [m] as written on a plot: '0.1 mm', '10 mm', '1.2 m', '50 µm'."""
    x = float(x)
    if abs(x) >= 1.0:
        return f"{x:.3g} m"
    if abs(x) >= 1e-4 or x == 0.0:
        return f"{x * 1e3:.3g} mm"
    return f"{x * 1e6:.3g} {MU}m"


def crater_scale(largest):
    """(scale, unit) for crater sizes up to `largest` [m]: mm, or µm for dents under 10 µm."""
    largest = abs(float(largest)) if largest == largest else 0.0
    return (1e6, MU + "m") if 0.0 < largest < 1e-5 else (1e3, "mm")


def mass_scale(largest, dimension=2):
    """(scale, unit) for masses up to `largest` [kg] (2D: per metre of the section's thickness, kg/m)."""
    per = "/m" if dimension == 2 else ""
    largest = abs(float(largest)) if largest == largest else 0.0
    for scale, unit in ((1.0, "kg"), (1e3, "g"), (1e6, "mg"), (1e9, MU + "g")):
        if largest * scale >= 1.0:
            break
    return scale, unit + per


def mass_label(dimension=2):
    """The words before the unit of an eroded mass axis."""
    return "eroded mass per metre of thickness" if dimension == 2 else "eroded mass"


def plain(text):
    """Text that matplotlib draws as written: no mathtext from a '$' in a case's title."""
    return str(text).replace("$", r"\$")


def material_text(name):
    """'Al6061_T6' -> 'Al6061 T6', 'OFHC_copper' -> 'OFHC copper'."""
    return str(name).replace("_", " ")


# A swept or --set key -> (words, unit, scale from the case file's SI value).
KEY_UNITS = (
    (r"pressure$", "MPa", 1e-6),
    (r"(velocity|traverse_speed)$", "m/s", 1.0),
    (r"mass_flow_rate$", "kg/s", 1.0),
    (r"(particle_spacing|spacing|diameter|standoff|radius_length)$", "mm", 1e3),
    (r"angle$", "\u00b0", 1.0),
    (r"(seed|ratio|cfl|count|layers|kernel|material|drag|solver)$", "-", 1.0),
)


def key_words(key):
    """'jet.pressure' -> 'jet pressure', 'inlet[0].velocity' -> 'inlet[0] velocity'."""
    return key.replace(".", " ").replace("_", " ")


def key_unit(key, values=()):
    """(unit, scale) of a case key's values as plotted; time keys in s, ms or µs as the values fit."""
    tail = key.rsplit(".", 1)[-1]
    if key.startswith("time.") or tail in ("end", "interval"):
        numbers = [abs(v) for v in values if isinstance(v, (int, float))]
        scale, unit = time_scale(max(numbers) if numbers else 0.0)
        return unit, scale
    for pattern, unit, scale in KEY_UNITS:
        if re.search(pattern, tail):
            return unit, scale
    return "SI", 1.0  # grit's case files are in SI units


def key_label(key, values=()):
    """An axis label for a swept key: 'jet pressure [MPa]'."""
    unit, _ = key_unit(key, values)
    return f"{key_words(key)} [{unit}]"


def key_value_text(key, value, values=()):
    """A swept value in its unit: 'jet pressure 150 MPa'."""
    unit, scale = key_unit(key, values)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        number = f"{value * scale:.4g}"
        return f"{key_words(key)} {number}" + ("" if unit in ("-", "SI") else ("" if unit == "\u00b0" else " ") + unit)
    return f"{key_words(key)} {material_text(value)}"


# --- the case and its parameters ------------------------------------------------------------------------

def fnv1a64(data):
    """grit's case_digest (src/grit/io/run_folder.cpp): FNV-1a, 64 bits, as 16 hex digits."""
    h = 14695981039346656037
    for byte in data:
        h = ((h ^ byte) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def parse_value(text):
    """A --set value as grit reads it: a TOML value, or else a bare word (a string)."""
    text = text.strip()
    if tomllib is not None:
        try:
            return tomllib.loads("v = " + text)["v"]
        except (tomllib.TOMLDecodeError, KeyError):
            return text
    try:
        return float(text)
    except ValueError:
        return text


def assign(table, parts, value):
    """Sets key path `parts` in a case's tables as grit's --set does: 'inlet[0]' one block of an array of
    tables, 'fluid' (an array without an index) every block of it."""
    name, rest = parts[0], parts[1:]
    index = None
    match = re.fullmatch(r"(.+)\[(\d+)\]", name)
    if match:
        name, index = match.group(1), int(match.group(2))
    if not rest:
        table[name] = value
        return
    here = table.get(name)
    if index is not None:
        if not isinstance(here, list):
            here = table[name] = []
        while len(here) <= index:
            here.append({})
        targets = [here[index]]
    elif isinstance(here, list):
        targets = [t for t in here if isinstance(t, dict)]
    else:
        if not isinstance(here, dict):
            here = table[name] = {}
        targets = [here]
    for t in targets:
        assign(t, rest, value)


def overrides(summary, raw=False):
    """The run's --set as {key: value} in the order given (raw: the values as typed)."""
    out = {}
    for item in summary.get("overrides") or []:
        key, eq, value = str(item).partition("=")
        if eq:
            out[key.strip()] = value.strip() if raw else parse_value(value)
    return out


def case_settings(summary):
    """The run's case as tables (its case file, if that is still the text the run was made with, with the
    run's --set applied), and the --set themselves. ({}, sets) where the case file cannot be read."""
    table = {}
    path = summary.get("case_file")
    if path and tomllib is not None:
        try:
            raw = pathlib.Path(path).read_bytes()
            if summary.get("case_digest") in (None, fnv1a64(raw)):
                table = tomllib.loads(raw.decode("utf-8"))
        except (OSError, ValueError, UnicodeDecodeError):
            table = {}
    sets = overrides(summary)
    for key, value in sets.items():
        try:
            assign(table, key.split("."), value)
        except (TypeError, AttributeError, IndexError):
            pass
    return table, sets


def _number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def key_parameters(summary):
    """[(slot, text, fallback)]: the run's key parameters in words. `slot` names what each one is (so that
    a sweep can tell those its runs share), `fallback` a shorter text that runs differing only in a
    derived value (the abrasive's mass flow) share, or None."""
    table, sets = case_settings(summary)
    items = []

    def was_set(*prefixes):
        return any(k == p or k.startswith(p + ".") or k.startswith(p + "[") for k in sets for p in prefixes)

    jet = table.get("jet") if isinstance(table.get("jet"), dict) else None
    inlets = [t for t in table.get("inlet", []) if isinstance(t, dict)] if isinstance(table.get("inlet"), list) else []
    source, name = (jet, "jet") if jet else (next((t for t in inlets if _number(t.get("velocity"))), None), "inlet")
    if source:
        parts = []
        if _number(source.get("diameter")):
            parts.append(length_text(source["diameter"]))
        if _number(source.get("velocity")):
            parts.append(f"{source['velocity']:.4g} m/s")
        if _number(source.get("pressure")):
            parts.append(f"{source['pressure'] * 1e-6:.4g} MPa")
        if parts:
            flag = " (--set)" if was_set("jet.velocity", "jet.pressure", "jet.diameter", "inlet") else ""
            items.append(("jet", f"{name} {', '.join(parts)}{flag}", None))
    abrasive = table.get("abrasive") if isinstance(table.get("abrasive"), dict) else {}
    rate = summary.get("abrasive_mass_flow_rate")
    if abrasive or _number(rate):
        material = material_text(abrasive["material"]) + " abrasive" if "material" in abrasive else "abrasive"
        text = material + (("," if material != "abrasive" else "") + f" {rate:.3g} kg/s" if _number(rate) else "")
        items.append(("abrasive", text, material))
    solids = [t for t in table.get("solid", []) if isinstance(t, dict)] if isinstance(table.get("solid"), list) else []
    names = list(dict.fromkeys(material_text(s["material"]) for s in solids if "material" in s))
    if names:
        items.append(("solid", "on " + " and ".join(names), None))
    if _number(summary.get("particle_spacing")):
        items.append(("spacing", f"particle spacing {length_text(summary['particle_spacing'])}", None))
    if summary.get("dimension") in (2, 3):
        items.append(("dimension", f"{summary['dimension']}D", None))
    shown = ("jet.", "inlet", "abrasive.", "numerics.particle_spacing", "solid", "time.", "output.")
    rest = [f"{k}={v}" for k, v in overrides(summary, raw=True).items() if not any(k.startswith(p) for p in shown)]
    if rest:
        items.append(("set", "--set " + ", ".join(rest), None))
    return items


def case_line(summary):
    """'case: title' (the title as the case file gives it; the title alone where it begins with the
    case's name)."""
    case, title = summary.get("case", ""), summary.get("title", "")
    if not title:
        return case
    if not case or title.lower().startswith(case.lower()):
        return title
    return f"{case}: {title}"


def run_heading(summary, width_in=8.0):
    """A figure's heading for one run: the case and its title, then its key parameters."""
    return wrap([case_line(summary), [text for _, text, _ in key_parameters(summary)]], width_in)


def swept_text(swept):
    """'jet pressure 150, 250 MPa' for {key: [values]}."""
    parts = []
    for key, values in swept.items():
        unit, scale = key_unit(key, values)
        numbers = all(_number(v) for v in values)
        shown = ", ".join(f"{v * scale:.4g}" if numbers else material_text(v) for v in values)
        unit = "" if unit in ("-", "SI") or not numbers else ("" if unit == "\u00b0" else " ") + unit
        parts.append(f"{key_words(key)} {shown}{unit}")
    return "; ".join(parts)


def sweep_heading(summaries, swept, width_in=8.0, extra=""):
    """A figure's heading for a sweep: the case, the parameters its runs share, what was swept ({key:
    [values]})."""
    summaries = [s for s in summaries if s]
    if not summaries:
        return wrap([f"sweep of {swept_text(swept)}" + extra], width_in)
    per_run = [{slot: (text, fallback) for slot, text, fallback in key_parameters(s)} for s in summaries]
    shared = []
    for slot, text, fallback in key_parameters(summaries[0]):
        texts = {run.get(slot, (None, None))[0] for run in per_run}
        if slot == "set":
            continue  # each run's --set holds its swept values
        if len(texts) == 1:
            shared.append(text.replace(" (--set)", ""))
        elif fallback and {run.get(slot, (None, None))[1] for run in per_run} == {fallback}:
            shared.append(fallback)
    sets = [overrides(s) for s in summaries]
    typed = overrides(summaries[0], raw=True)
    common = [f"{k}={typed[k]}" for k, v in sets[0].items()
              if k not in swept and not k.startswith(("time.", "output.")) and all(s.get(k) == v for s in sets)]
    if common:
        shared.append("--set " + ", ".join(common))
    return wrap([case_line(summaries[0]), shared, f"sweep of {swept_text(swept)}" + extra], width_in)


def wrap(lines, width_in):
    """Lines wrapped to a figure `width_in` inches wide (at the headings' 9 points); a line given as a
    list of items is joined with ' · ', broken between items where it can be."""
    width = max(40, int(width_in * 13))
    out = []
    for line in lines:
        if isinstance(line, str):
            if line:
                out.append(textwrap.fill(line, width, break_long_words=False))
            continue
        current = ""
        for item in line:
            joined = f"{current}{SEP}{item}" if current else item
            if current and len(joined) > width:
                out.append(current)
                current = item
            else:
                current = joined
            if len(current) > width:  # one item longer than a line: wrapped on its own
                pieces = textwrap.wrap(current, width, break_long_words=False)
                out.extend(pieces[:-1])
                current = pieces[-1]
        if current:
            out.append(current)
    return plain("\n".join(out))
