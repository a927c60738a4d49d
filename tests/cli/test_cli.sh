#!/usr/bin/env bash
# CLI tests of grit: exit codes and one-line messages for bad input and bad command lines, --version,
# the files of a run, VTK-readable output, identical results with 1 and 2 threads, and a reported blow-up.
#
# Usage: bash tests/cli/test_cli.sh <path-to-grit> <repo-root> [<python3-with-vtk>]
# Works from any current directory. Prints one line per check and a final "N passed, M failed".
set -euo pipefail

if [[ $# -lt 2 ]]; then
    echo "usage: $0 <path-to-grit> <repo-root> [<python3-with-vtk>]" >&2
    exit 2
fi
GRIT=$(realpath -- "$1")
ROOT=$(realpath -- "$2")
PY=${3:-}
if [[ ! -x $GRIT ]]; then
    echo "error: $GRIT is not an executable" >&2
    exit 2
fi
if [[ ! -d $ROOT/cases ]]; then
    echo "error: $ROOT is not the grit repository root (no cases/)" >&2
    exit 2
fi

W=$(mktemp -d "${TMPDIR:-/tmp}/grit_cli.XXXXXX")
trap 'rm -rf -- "$W"' EXIT
cd "$W"  # nothing below depends on the caller's directory

HYDRO=$ROOT/cases/hydrostatic_2d/case.toml
JET=$ROOT/cases/jet_on_wall_2d/case.toml
CHECKER=$ROOT/tests/unit/io/check_vtu_with_vtk.py
ARRAYS=(velocity density pressure mass phase)

passed=0
failed=0
failures=()
pass() { echo "PASS: $1"; passed=$((passed + 1)); }
fail() {
    echo "FAIL: $1${2:+ -- $2}"
    failed=$((failed + 1))
    failures+=("$1")
}
skip() { echo "SKIPPED: $1 ($2)"; }

# A python able to run the VTK checker, and one able to parse JSON (any python3).
HAVE_VTK=0
VTK_WHY="no python given"
if [[ -n $PY ]]; then
    if [[ -x $PY ]] && "$PY" -c 'import vtk' >/dev/null 2>&1; then
        HAVE_VTK=1
    else
        VTK_WHY="$PY cannot import vtk"
    fi
fi
JSON_PY=""
if [[ -n $PY && -x $PY ]]; then
    JSON_PY=$PY
elif command -v python3 >/dev/null 2>&1; then
    JSON_PY=$(command -v python3)
fi

# Runs grit with the given arguments; sets RC and leaves stdout/stderr in $W/stdout, $W/stderr.
RC=0
grit() {
    RC=0
    "$GRIT" "$@" >"$W/stdout" 2>"$W/stderr" || RC=$?
}

# Runs the VTK checker on the arguments; sets VTK_RC and VTK_OUT.
VTK_RC=0
VTK_OUT=""
vtk_check() {
    VTK_RC=0
    VTK_OUT=$("$PY" "$CHECKER" "$@" 2>&1) || VTK_RC=$?
}

# expect_input_error NAME PATTERN... -- GRIT-ARGS...: grit must exit 2, print exactly one stderr line
# "grit: error: ..." containing every PATTERN, and leave $W/bad uncreated.
expect_input_error() {
    local name=$1
    shift
    local patterns=()
    while [[ $1 != -- ]]; do
        patterns+=("$1")
        shift
    done
    shift
    rm -rf -- "$W/bad"
    grit "$@" --out "$W/bad"
    local err lines why=""
    err=$(cat "$W/stderr")
    lines=$(grep -c '' "$W/stderr" || true)
    if [[ $RC -ne 2 ]]; then
        why="exit code $RC, expected 2"
    elif [[ $lines -ne 1 ]]; then
        why="$lines lines on stderr, expected 1"
    elif [[ $err != "grit: error: "* ]]; then
        why="stderr does not start with 'grit: error: '"
    elif [[ -e $W/bad ]]; then
        why="the output folder was created"
    else
        local p
        for p in "${patterns[@]}"; do
            if ! grep -qF -- "$p" "$W/stderr"; then
                why="'$p' missing from stderr"
                break
            fi
        done
    fi
    if [[ -z $why ]]; then
        pass "bad input: $name -> exit 2: $err"
    else
        fail "bad input: $name" "$why; stderr: $err"
    fi
    rm -rf -- "$W/bad"
}

# expect_usage_error NAME PATTERN... -- GRIT-ARGS...: grit must exit 2 and print exactly one short stderr
# line (under 200 characters) "grit: error: ..." containing every PATTERN, and nothing on stdout.
expect_usage_error() {
    local name=$1
    shift
    local patterns=()
    while [[ $1 != -- ]]; do
        patterns+=("$1")
        shift
    done
    shift
    grit "$@"
    local err lines why=""
    err=$(cat "$W/stderr")
    lines=$(grep -c '' "$W/stderr" || true)
    if [[ $RC -ne 2 ]]; then
        why="exit code $RC, expected 2"
    elif [[ $lines -ne 1 ]]; then
        why="$lines lines on stderr, expected 1"
    elif [[ $err != "grit: error: "* ]]; then
        why="stderr does not start with 'grit: error: '"
    elif [[ ${#err} -ge 200 ]]; then
        why="${#err} characters on stderr, expected under 200"
    elif [[ -s $W/stdout ]]; then
        why="stdout not empty: $(head -c 200 "$W/stdout")"
    else
        local p
        for p in "${patterns[@]}"; do
            if ! grep -qF -- "$p" "$W/stderr"; then
                why="'$p' missing from stderr"
                break
            fi
        done
    fi
    if [[ -z $why ]]; then
        pass "usage: $name -> exit 2: $err"
    else
        fail "usage: $name" "$why; stderr: $(head -c 400 "$W/stderr")"
    fi
}

# --- the material library and a valid case ---------------------------------------------------------

grit materials
if [[ $RC -eq 0 ]] && grep -qx 'water' "$W/stdout"; then
    pass "grit materials exits 0 and lists water"
else
    fail "grit materials exits 0 and lists water" "exit $RC"
fi

grit check "$HYDRO"
if [[ $RC -eq 0 ]]; then
    pass "grit check cases/hydrostatic_2d/case.toml exits 0"
else
    fail "grit check cases/hydrostatic_2d/case.toml exits 0" "exit $RC: $(cat "$W/stderr")"
fi

# Every case file shipped in cases/ reads and checks: a case a user copies must not be broken.
bad_cases=()
while IFS= read -r -d '' c; do
    grit check "$c"
    [[ $RC -eq 0 ]] || bad_cases+=("${c#"$ROOT"/}: $(head -n 1 "$W/stderr")")
done < <(find "$ROOT/cases" -name '*.toml' -print0 | sort -z)
if [[ ${#bad_cases[@]} -eq 0 ]]; then
    pass "grit check passes every case file in cases/"
else
    fail "grit check passes every case file in cases/" "${bad_cases[*]}"
fi

# --- bad input: exit code 2, one line naming the key (or file) and the reason, nothing written --------

sed 's/^smoothing_ratio *=/smoothing_ratoi =/' "$HYDRO" >"$W/typo.toml"
expect_input_error "unknown key in the file, with a suggestion" "numerics.smoothing_ratoi" "unknown key" \
    "did you mean 'smoothing_ratio'?" -- run "$W/typo.toml"
expect_input_error "unknown key through --set" "numerics.particle_spacng" "unknown key" -- \
    run "$HYDRO" --set numerics.particle_spacng=0.02
expect_input_error "negative spacing" "numerics.particle_spacing" "-0.01" "must be positive" -- \
    run "$HYDRO" --set numerics.particle_spacing=-0.01
expect_input_error "negative surface triaxiality of eq. (35)" "materials.OFHC_copper.failure_surface_triaxiality" \
    "-1" "must be positive" -- run "$ROOT/cases/demo.toml" --set materials.OFHC_copper.failure_surface_triaxiality=-1
expect_input_error "negative damage length (non-local damage)" "materials.OFHC_copper.damage_length" \
    "-0.0003" "must not be negative" -- run "$ROOT/cases/demo.toml" --set materials.OFHC_copper.damage_length=-3e-4
expect_input_error "unknown material" "fluid[0].material" "unobtainium" "unknown material" -- \
    run "$HYDRO" --set 'fluid[0].material=unobtainium'
expect_input_error "unknown kernel" "numerics.kernel" "gauss" "must be one of" -- \
    run "$HYDRO" --set numerics.kernel=gauss
expect_input_error "3 numbers in a 2D case" "physics.gravity" "must be an array of 2 numbers" -- \
    run "$HYDRO" --set 'physics.gravity=[0.0, -9.81, 0.0]'
expect_input_error "missing file" "$W/no_such_case.toml" "no such file" -- run "$W/no_such_case.toml"
printf '# line 1\n\n[time\nend = 1.0\n' >"$W/malformed.toml"
expect_input_error "malformed TOML" "$W/malformed.toml" "line 3" "malformed TOML" -- run "$W/malformed.toml"
expect_input_error "spacing larger than the geometry" "fluid[0].max" "less than numerics.particle_spacing" -- \
    run "$HYDRO" --set numerics.particle_spacing=1.0
expect_input_error "negative --end-time" "--end-time" "must not be negative" -- run "$HYDRO" --end-time -1
expect_input_error "--set without '='" "--set 'time.end'" "key.path=value" -- run "$HYDRO" --set time.end
expect_input_error "a bad --set that --end-time replaces" "time.end" "must not be negative" -- \
    run "$HYDRO" --set time.end=-1 --end-time 0
expect_input_error "particles beyond the machine's memory" "numerics.particle_spacing" "more than this machine's" -- \
    run "$ROOT/cases/dambreak_3d/case.toml" --set numerics.particle_spacing=0.0004 --set numerics.max_particles=1000000000

# STL mesh walls: a file that cannot be trusted is refused with its name and the problem.
WEAR=$ROOT/cases/wear_angle_sweep_3d/case.toml
expect_input_error "missing STL file" "no_such.stl" "no such file" -- run "$WEAR" --set 'mesh[0].file=no_such.stl'
: >"$W/empty.stl"
expect_input_error "empty STL file" "$W/empty.stl" "empty" -- run "$WEAR" --set "mesh[0].file=$W/empty.stl"
printf 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 2 0 0\nendloop\nendfacet\nendsolid\n' \
    >"$W/flat.stl"
expect_input_error "degenerate STL facet" "$W/flat.stl" "facet 1 is degenerate" -- run "$WEAR" --set "mesh[0].file=$W/flat.stl"
head -n -8 "$ROOT/cases/wear_angle_sweep_3d/plate.stl" >"$W/cut.stl"  # the last facet and endsolid cut off
expect_input_error "STL file cut short" "$W/cut.stl" "cut short" -- run "$WEAR" --set "mesh[0].file=$W/cut.stl"
expect_input_error "open STL where it must be watertight" "plate.stl" "16 open edges" "watertight" -- \
    run "$WEAR" --set 'mesh[0].watertight=true'
expect_input_error "unknown wear model" "mesh[0].wear_model" "archard" -- run "$WEAR" --set 'mesh[0].wear_model=archard'
HARD=(--set 'mesh[0].wear_material="hard"' --set 'wear_materials.hard.based_on="steel"')
expect_input_error "Bitter's deformation factor neither a number nor \"oka\"" "wear_materials.hard.bitter_deformation_factor" \
    "\"foo\"" "a number [J/m^3] or \"oka\"" -- run "$WEAR" "${HARD[@]}" --set 'wear_materials.hard.bitter_deformation_factor="foo"'
expect_input_error "a calibration speed for a given deformation factor" "wear_materials.hard.bitter_calibration_speed" \
    "only with bitter_deformation_factor = \"oka\"" -- run "$WEAR" "${HARD[@]}" \
    --set 'wear_materials.hard.bitter_deformation_factor=1e11' --set 'wear_materials.hard.bitter_calibration_speed=50'
MEMBRANE=$ROOT/cases/hydrostatic_membrane_3d/case.toml
expect_input_error "thin wall round a closed side" "wall[1].thin" "side = \"front\" or \"back\"" "\"outside\"" -- \
    run "$MEMBRANE" --set 'wall[1].side=outside'

# Too many particles: refused before anything is allocated (it used to end in std::bad_alloc, exit 1).
DAM=$ROOT/cases/dambreak_2d/case.toml
expect_input_error "spacing 1e-12: too many particles" "numerics.particle_spacing = 1e-12 m" "particles (~" \
    "bytes)" "numerics.max_particles = 20000000" -- run "$DAM" --set numerics.particle_spacing=1e-12
if grep -q 'bad_alloc' "$W/stderr"; then
    fail "spacing 1e-12: no bad_alloc" "stderr: $(cat "$W/stderr")"
else
    pass "spacing 1e-12: no bad_alloc"
fi
expect_usage_error "check with spacing 1e-12" "numerics.particle_spacing" "numerics.max_particles" -- \
    check "$DAM" --set numerics.particle_spacing=1e-12
# The dam break makes 23018 particles, which its estimate matches exactly.
expect_usage_error "numerics.max_particles below the count" "about 2.3e+04 particles" \
    "numerics.max_particles = 23017" -- check "$DAM" --set numerics.max_particles=23017
grit check "$DAM" --set numerics.max_particles=23018
if [[ $RC -eq 0 ]]; then
    pass "numerics.max_particles = 23018 (the dam break's count) passes check"
else
    fail "numerics.max_particles = 23018 (the dam break's count) passes check" "exit $RC: $(cat "$W/stderr")"
fi
expect_usage_error "numerics.max_particles = 0" "numerics.max_particles" "must lie in" -- \
    check "$DAM" --set numerics.max_particles=0

# check --pipeline: the stages in step order, each with its module. The half water jet on copper runs the
# symmetry plane, whose stages close each hook they share with the forces it mirrors.
grit check "$ROOT/cases/waterjet_copper_2d/half.toml" --pipeline
stages=$(sed -n '/^pipeline (/,$p' "$W/stdout")
if [[ $RC -eq 0 ]] && grep -q "^  force  *sph_fluid  *sph  *yes$" <<<"$stages" &&
   [[ $(grep -c "symmetry_plane" <<<"$stages") -gt 0 ]] &&
   awk '$1 == "force" { last = $3 } END { exit !(last == "symmetry_plane") }' <<<"$stages" &&
   [[ $(tail -1 <<<"$stages" | awk '{print $2, $3}') == "time_step simulation" ]]; then
    pass "check --pipeline: stages in order with their modules, the symmetry plane last at force"
else
    fail "check --pipeline: stages in order with their modules" "exit $RC: $stages $(cat "$W/stderr")"
fi

# --- command-line errors: exit 2, one short line; --help and --version exit 0 ----------------------------

expect_usage_error "--threads -3" "--threads -3" "positive whole number" -- run "$HYDRO" --threads -3
expect_usage_error "--threads abc" "--threads abc" "positive whole number" -- run "$HYDRO" --threads abc
expect_usage_error "unknown option" "--bogus" -- run "$HYDRO" --bogus
expect_usage_error "missing case file" "case is required" -- run
expect_usage_error "no command" "a command is required" --
expect_usage_error "unknown command" "frob" "unknown command" -- frob

VERSION=$(sed -n 's/^project(grit VERSION \([0-9.]*\).*/\1/p' "$ROOT/CMakeLists.txt")
grit --version
if [[ $RC -eq 0 ]] && [[ -n $VERSION ]] && grep -Eq "^grit $VERSION \(git [0-9a-z.-]+\)$" "$W/stdout"; then
    pass "grit --version exits 0 and prints 'grit $VERSION (git REVISION)': $(cat "$W/stdout")"
else
    fail "grit --version exits 0 and prints 'grit $VERSION (git REVISION)'" "exit $RC: $(cat "$W/stdout" "$W/stderr")"
fi
grit --help
if [[ $RC -eq 0 ]] && grep -q 'run' "$W/stdout" && grep -q -- '--version' "$W/stdout"; then
    pass "grit --help exits 0 and lists the commands"
else
    fail "grit --help exits 0 and lists the commands" "exit $RC"
fi

# --- a zero-length run: the files it writes ----------------------------------------------------------

T0=$W/t0
grit run "$HYDRO" --end-time 0 --out "$T0" --quiet
if [[ $RC -eq 0 ]]; then
    pass "run --end-time 0 exits 0"
else
    fail "run --end-time 0 exits 0" "exit $RC: $(cat "$W/stderr")"
fi

if [[ -f $T0/hydrostatic_2d.pvd ]]; then
    pass "t0: hydrostatic_2d.pvd written"
else
    fail "t0: hydrostatic_2d.pvd written"
fi

shopt -s nullglob
vtus=("$T0"/snapshots/*.vtu)
if [[ ${#vtus[@]} -eq 1 ]]; then
    pass "t0: exactly one snapshots/*.vtu"
else
    fail "t0: exactly one snapshots/*.vtu" "found ${#vtus[@]}"
fi

HEADER='time,step,dt,kinetic_energy,mass_total,mass_in,mass_out,max_velocity'
if [[ -f $T0/series.csv ]] && [[ $(head -n 1 "$T0/series.csv") == "$HEADER"* ]] &&
    [[ $(grep -c '' "$T0/series.csv") -eq 2 ]]; then
    pass "t0: series.csv has the header and one data row"
else
    fail "t0: series.csv has the header and one data row" \
        "$( [[ -f $T0/series.csv ]] && head -n 3 "$T0/series.csv" | tr '\n' '|' || echo missing)"
fi

if [[ -f $T0/run.log ]] && grep -q 'grit .* (git ' "$T0/run.log" && grep -q 'estimate: ~' "$T0/run.log" &&
    grep -q '\[info\] completed: ' "$T0/run.log"; then
    pass "t0: run.log names the version, the estimate and the end"
else
    fail "t0: run.log names the version, the estimate and the end" "$(cat "$T0/run.log" 2>&1)"
fi

# Progress in every log: with standard error not a terminal (make, tee, a batch job), a plain line every
# --progress-every seconds, in run.log too.
grit run "$ROOT/cases/demo.toml" --set time.end=4e-6 --set output.snapshots=false --out "$W/progress" --progress-every 0.2
if [[ $RC -eq 0 ]] && grep -Eq '^progress: +[0-9.]+% t = .* s, step [0-9]+, .* steps/s, elapsed .*, (ETA|done)' "$W/stderr" &&
    grep -q '\[info\] progress: ' "$W/progress/run.log" && ! grep -q $'\r' "$W/stderr"; then
    pass "progress lines when standard error is not a terminal, and in run.log: $(grep -m1 '^progress' "$W/stderr")"
else
    fail "progress lines when standard error is not a terminal, and in run.log" "exit $RC: $(head -c 600 "$W/stderr")"
fi

# How many threads a run uses (parallel/thread_governor.hpp): fewer while another process holds a core,
# unless --fixed-threads; run.log says so, summary.json counts the changes.
T0W=$W/t0_threads
"$GRIT" run "$HYDRO" --end-time 1e-3 --threads 2 --out "$T0W" --quiet >/dev/null 2>&1
adapting=$(grep -c 'threads: 2, fewer while another process holds a core' "$T0W/run.log" 2>/dev/null || true)
changes=$(grep -c '"thread_changes":' "$T0W/summary.json" 2>/dev/null || true)
"$GRIT" run "$HYDRO" --end-time 1e-3 --threads 2 --fixed-threads --out "$T0W" --overwrite --quiet >/dev/null 2>&1
fixed=$(grep -c 'fewer while another process' "$T0W/run.log" 2>/dev/null || true)
fixed_changes=$(grep -c '"thread_changes":' "$T0W/summary.json" 2>/dev/null || true)
if [[ $adapting == 1 && $changes == 1 && $fixed == 0 && $fixed_changes == 0 ]]; then
    pass "run: threads adapt to the machine's load unless --fixed-threads (run.log, summary.json)"
else
    fail "run: threads adapt to the machine's load unless --fixed-threads" \
        "adapting: $adapting, changes: $changes; with --fixed-threads: $fixed, $fixed_changes"
fi

KEYS=(particles steps wall_time_s particle_steps_per_second end_time git_revision)
if [[ ! -f $T0/summary.json ]]; then
    fail "t0: summary.json has the run's keys" "missing"
elif [[ -n $JSON_PY ]]; then
    json_rc=0
    json_out=$("$JSON_PY" -c '
import json, sys
d = json.load(open(sys.argv[1]))
missing = [k for k in sys.argv[2:] if k not in d]
if missing:
    sys.exit("missing keys: " + ", ".join(missing))
if d["steps"] != 0 or d["end_time"] != 0 or d["particles"] <= 0:
    sys.exit("unexpected values: steps=%r end_time=%r particles=%r" % (d["steps"], d["end_time"], d["particles"]))
' "$T0/summary.json" "${KEYS[@]}" 2>&1) || json_rc=$?
    if [[ $json_rc -eq 0 ]]; then
        pass "t0: summary.json has the run's keys"
    else
        fail "t0: summary.json has the run's keys" "$json_out"
    fi
else
    missing=""
    for k in "${KEYS[@]}"; do grep -q "\"$k\"" "$T0/summary.json" || missing+=" $k"; done
    if [[ -z $missing ]]; then
        pass "t0: summary.json has the run's keys (grep; no python)"
    else
        fail "t0: summary.json has the run's keys" "missing:$missing"
    fi
fi

if [[ $HAVE_VTK -eq 1 ]]; then
    vtk_check --pvd "$T0/hydrostatic_2d.pvd" "${ARRAYS[@]}"
    if [[ $VTK_RC -eq 0 ]]; then
        pass "t0: VTK reads the .pvd and its .vtu"
    else
        fail "t0: VTK reads the .pvd and its .vtu" "$VTK_OUT"
    fi
    if [[ $VTK_OUT == *"field data: material_names=[tank_water]; phase_names=[fluid, solid, wall]"* ]]; then
        pass "t0: snapshots name the materials and phases (field data)"
    else
        fail "t0: snapshots name the materials and phases (field data)" "$VTK_OUT"
    fi
else
    skip "t0: VTK reads the .pvd and its .vtu" "$VTK_WHY"
fi

# --- grains: a short drop test writes grains/*.vtu and impacts.csv; bad grain input is refused -------

BOUNCE=$ROOT/cases/dem_bounce_2d/case.toml
G=$W/grains
grit run "$BOUNCE" --end-time 0.12 --out "$G" --quiet
if [[ $RC -eq 0 ]]; then
    pass "grains: the drop test runs to 0.12 s"
else
    fail "grains: the drop test runs to 0.12 s" "exit $RC: $(cat "$W/stderr")"
fi
if [[ -f $G/impacts.csv ]] && [[ $(head -n 1 "$G/impacts.csv") == "time,grain,target,speed,angle,x,y,grain_collisions" ]] &&
    grep -q ",$((5 << 56)),floor," "$G/impacts.csv"; then  # the grain's id: grain block 0, serial 0
    pass "grains: impacts.csv has its header and the floor impact"
else
    fail "grains: impacts.csv has its header and the floor impact" \
        "$( [[ -f $G/impacts.csv ]] && head -n 3 "$G/impacts.csv" | tr '\n' '|' || echo missing)"
fi
gvtus=("$G"/grains/*.vtu)
if [[ ${#gvtus[@]} -ge 2 ]] && [[ -f $G/dem_bounce_2d_grains.pvd ]]; then
    pass "grains: grains/*.vtu and the grains .pvd written"
else
    fail "grains: grains/*.vtu and the grains .pvd written" "found ${#gvtus[@]} files"
fi
if [[ $HAVE_VTK -eq 1 ]]; then
    vtk_check --pvd "$G/dem_bounce_2d_grains.pvd" radius velocity angular_velocity force
    if [[ $VTK_RC -eq 0 ]]; then
        pass "grains: VTK reads grains/*.vtu with radius, velocity, angular_velocity, force"
    else
        fail "grains: VTK reads grains/*.vtu with radius, velocity, angular_velocity, force" "$VTK_OUT"
    fi
else
    skip "grains: VTK reads grains/*.vtu" "$VTK_WHY"
fi
expect_input_error "unknown grain material" "grains[0].material" "diamond" "built-in grain material" -- \
    run "$BOUNCE" --set "grains[0].material=diamond"
expect_input_error "restitution out of range" "grain_materials.drop_grain.restitution" "1.5" -- \
    run "$BOUNCE" --set grain_materials.drop_grain.restitution=1.5

# A grain placed in the contact zone of the wall particles (closer than a spacing to its surface) is
# warned of, by its id; the case as shipped is not.
SEDIMENT=$ROOT/cases/sedimentation_2d/case.toml
grit run "$SEDIMENT" --set 'grains[0].position=[1.0e-3, 1.0e-4]' --set time.end=1e-12 --out "$W/in_contact" --quiet
if [[ $RC -eq 0 ]] && grep -q "1 grain(s) start in contact with SPH wall or solid" "$W/stderr" &&
    grep -q "grain $((5 << 56)) (grain block 0, serial 0) at (0.001, 0.0001) m" "$W/stderr" &&
    ! grep -q "start in contact" "$W/stdout"; then
    pass "a grain starting in contact with the wall particles is warned of"
else
    fail "a grain starting in contact with the wall particles is warned of" "rc $RC: $(head -c 300 "$W/stderr")"
fi
grit run "$SEDIMENT" --set time.end=1e-12 --out "$W/clear_of_walls" --quiet
if [[ $RC -eq 0 ]] && ! cat "$W/stdout" "$W/stderr" | grep -q "start in contact"; then
    pass "a grain clear of the walls is not warned of"
else
    fail "a grain clear of the walls is not warned of" "rc $RC: $(head -c 300 "$W/stderr")"
fi

# Periodic axes: domain.periodic and its older spelling dem.periodic must agree; a periodic axis must be
# longer than twice the kernel support, and than twice the crack analysis' link distance.
POIS=$ROOT/cases/poiseuille_periodic_2d/case.toml
grit check "$POIS"
if [[ $RC -eq 0 ]]; then
    pass "grit check cases/poiseuille_periodic_2d/case.toml exits 0"
else
    fail "grit check cases/poiseuille_periodic_2d/case.toml exits 0" "exit $RC: $(cat "$W/stderr")"
fi
expect_input_error "domain.periodic and dem.periodic differ" "'domain.periodic' = [\"x\"]" \
    "'dem.periodic' = [\"y\"]" "differ" -- run "$BOUNCE" --set 'domain.periodic=["x"]' --set 'dem.periodic=["y"]'
expect_input_error "periodic axis not longer than two kernel supports" "key 'domain.periodic'" \
    "twice the kernel support" -- run "$POIS" --set 'domain.max=[1.0e-4, 1.1e-3]' \
    --set 'fluid[0].max=[1.0e-4, 9.875e-4]' --set 'wall[0].max=[1.0e-4, 1.25e-5]' \
    --set 'wall[1].max=[1.0e-4, 1.0625e-3]'
expect_input_error "crack link of half the period" "key 'cracks.link_distance' = 0.011" "two images" -- \
    run "$ROOT/cases/elastic_bar_periodic_2d/case.toml" --set 'cracks.link_distance=0.011'

# --- determinism: 1 and 2 threads give the same bytes ------------------------------------------------

jet_ok=1
for t in 1 2; do
    grit run "$JET" --set time.end=2e-5 --set output.interval=1e-5 --quiet --threads "$t" --out "$W/jet$t"
    if [[ $RC -ne 0 ]]; then
        jet_ok=0
        fail "jet_on_wall_2d with --threads $t exits 0" "exit $RC: $(cat "$W/stderr")"
    fi
done
if [[ $jet_ok -eq 1 ]]; then
    if cmp -s "$W/jet1/series.csv" "$W/jet2/series.csv"; then
        pass "threads 1 vs 2: series.csv byte-identical"
    else
        fail "threads 1 vs 2: series.csv byte-identical" "$(cmp "$W/jet1/series.csv" "$W/jet2/series.csv" 2>&1 || true)"
    fi
    snaps1=("$W"/jet1/snapshots/*.vtu)
    snaps2=("$W"/jet2/snapshots/*.vtu)
    if [[ ${#snaps1[@]} -lt 2 || ${#snaps1[@]} -ne ${#snaps2[@]} ]]; then
        fail "threads 1 vs 2: last snapshot byte-identical" "${#snaps1[@]} vs ${#snaps2[@]} snapshots"
    else
        last1=${snaps1[-1]}
        last2=$W/jet2/snapshots/$(basename -- "$last1")
        if cmp -s "$last1" "$last2"; then
            pass "threads 1 vs 2: last snapshot $(basename -- "$last1") byte-identical"
        else
            fail "threads 1 vs 2: last snapshot byte-identical" "$(cmp "$last1" "$last2" 2>&1 || true)"
        fi
    fi
fi

# --- a blow-up: exit 3, a message naming the step and the particle, a readable last good state --------

BU=$W/blowup
grit run "$HYDRO" --set time.cfl=1.0 --set numerics.density_diffusion=0 \
    --set materials.tank_water.artificial_viscosity_alpha=0 \
    --set materials.tank_water.artificial_viscosity_beta=0 --end-time 2 --out "$BU" --quiet
if [[ $RC -eq 3 ]]; then
    pass "blow-up exits 3"
else
    fail "blow-up exits 3" "exit $RC"
fi
if grep 'blow-up at step' "$W/stderr" | grep -q 'particle'; then
    pass "blow-up: stderr names the step and the particle"
else
    fail "blow-up: stderr names the step and the particle" "stderr: $(cat "$W/stderr")"
fi
last_good=("$BU"/snapshots/*last_good*.vtu)
if [[ ${#last_good[@]} -eq 1 ]]; then
    pass "blow-up: $(basename -- "${last_good[0]}") written"
    if [[ $HAVE_VTK -eq 1 ]]; then
        vtk_check "${last_good[0]}" "${ARRAYS[@]}"
        if [[ $VTK_RC -eq 0 ]]; then
            pass "blow-up: VTK reads the last good state"
        else
            fail "blow-up: VTK reads the last good state" "$VTK_OUT"
        fi
    else
        skip "blow-up: VTK reads the last good state" "$VTK_WHY"
    fi
else
    fail "blow-up: one snapshots/*last_good*.vtu written" "found ${#last_good[@]}"
fi

# --- checkpoints and restart: killed (SIGKILL) or interrupted (SIGINT) runs continue bit for bit -------

DEMO=$ROOT/cases/demo.toml
DEMO_SET=(--set time.end=1.2e-5 --set output.interval=1e-6 --set output.checkpoint_interval=1e-6 --threads 2 --quiet)
# Files that must be identical to the straight run's.
same_outputs() {
    local a=$1 b=$2 f rel
    while IFS= read -r f; do
        rel=${f#"$a"/}
        cmp -s -- "$f" "$b/$rel" || { echo "$rel differs"; return 1; }
    done < <(find "$a" -type f \( -name '*.csv' -o -name '*.pvd' -o -name '*.vtu' \) ! -name '*interrupted*')
    return 0
}
# Starts grit in the background and waits for its first checkpoint; sets BG_PID.
start_and_wait_for_checkpoint() {
    local dir=$1
    shift
    "$GRIT" run "$DEMO" --out "$dir" "${DEMO_SET[@]}" "$@" >"$W/bg_out" 2>"$W/bg_err" &
    BG_PID=$!
    local k
    for k in $(seq 1 600); do
        compgen -G "$dir/checkpoints/checkpoint_*.h5" >/dev/null && return 0
        sleep 0.05
    done
    return 1
}

STRAIGHT=$W/straight
grit run "$DEMO" --out "$STRAIGHT" "${DEMO_SET[@]}"
ckpts=("$STRAIGHT"/checkpoints/checkpoint_*.h5)
if [[ $RC -eq 0 && ${#ckpts[@]} -eq 2 ]]; then
    pass "demo with output.checkpoint_interval: exit 0, the latest 2 checkpoints kept"
else
    fail "demo with output.checkpoint_interval: exit 0, the latest 2 checkpoints kept" "exit $RC, ${#ckpts[@]} checkpoints"
fi
if [[ $(head -n 1 "$STRAIGHT/crater.csv") == "x,surface,time" ]]; then
    pass "crater.csv starts with its header row"
else
    fail "crater.csv starts with its header row" "first line: $(head -n 1 "$STRAIGHT/crater.csv")"
fi
# Nothing is eroded in the demo's first 12 us: first_removal_time is null (JSON has no NaN).
if grep -q '"eroded_mass": 0.0,' "$STRAIGHT/summary.json" && grep -q '"first_removal_time": null,' "$STRAIGHT/summary.json"; then
    pass "summary.json: first_removal_time is null while nothing has been eroded"
else
    fail "summary.json: first_removal_time is null while nothing has been eroded" \
        "$(grep -E '"(eroded_mass|first_removal_time)"' "$STRAIGHT/summary.json" 2>&1)"
fi
# crater_history.csv: the profile of every output (13: 0 to 12 us), the last one crater.csv's rows.
bins=$(($(wc -l <"$STRAIGHT/crater.csv") - 1))
history_times=$(tail -n +2 "$STRAIGHT/crater_history.csv" 2>/dev/null | cut -d, -f3 | sort -u | wc -l)
if [[ $(head -n 1 "$STRAIGHT/crater_history.csv" 2>/dev/null) == "x,surface,time" && $history_times -eq 13 &&
    $(($(wc -l <"$STRAIGHT/crater_history.csv") - 1)) -eq $((13 * bins)) ]] &&
    cmp -s <(tail -n "$bins" "$STRAIGHT/crater_history.csv") <(tail -n +2 "$STRAIGHT/crater.csv"); then
    pass "crater_history.csv holds the profile of each of the 13 outputs, the last one crater.csv's"
else
    fail "crater_history.csv holds the profile of each output" \
        "$history_times output times, $(wc -l <"$STRAIGHT/crater_history.csv" 2>/dev/null) lines for $bins bins"
fi
# `grit crater DIR` measures every output of crater_history.csv again: its crater_measures.csv must give
# series.csv's crater columns at each output time (both written to 9 digits), and at least `min_deep`
# outputs must have a crater deeper than the surface's noise (C_d > 0).
remeasure_matches_series() {
    local dir=$1 min_deep=$2
    grit crater "$dir"
    [[ $RC -eq 0 && -s "$dir/crater_measures.csv" && -n $JSON_PY ]] || return 1
    "$JSON_PY" - "$dir/crater_measures.csv" "$dir/series.csv" "$min_deep" <<'PYEOF'
import csv, math, sys
measures = list(csv.DictReader(open(sys.argv[1])))
series = {float(r["time"]): r for r in csv.DictReader(open(sys.argv[2]))}
cols = [c for c in measures[0] if c != "time"]
deep = 0
for m in measures:
    t = float(m["time"])
    row = next((r for ts, r in series.items() if abs(ts - t) <= 1e-9 * max(abs(t), 1e-12)), None)
    if row is None:
        sys.exit(f"no series.csv row at t = {t}")
    for c in cols:
        a, b = float(m[c]), float(row[c])
        if not math.isclose(a, b, rel_tol=1e-7, abs_tol=1e-15):
            sys.exit(f"t = {t}: {c} {a} in crater_measures.csv, {b} in series.csv")
    deep += float(m["crater_depth"]) > 0
sys.exit(0 if len(measures) == len(series) and deep >= int(sys.argv[3]) else f"{len(measures)} outputs, {deep} with a crater")
PYEOF
}
if [[ -n $JSON_PY ]] && "$JSON_PY" -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if j["restarted_from"] is None else 1)' "$STRAIGHT/summary.json"; then
    pass "summary.json: restarted_from is null for a fresh run"
else
    fail "summary.json: restarted_from is null for a fresh run"
fi
if command -v h5dump >/dev/null 2>&1; then
    # Capture first: with pipefail, grep -q closing the pipe early would
    # fail the pipeline through h5dump's SIGPIPE.
    ckpt_attrs=$(h5dump -A "${ckpts[-1]}" 2>/dev/null || true)
    if grep -q 'case_text' <<<"$ckpt_attrs"; then
        pass "checkpoint is readable by h5dump (case_text attribute)"
    else
        fail "checkpoint is readable by h5dump (case_text attribute)"
    fi
else
    skip "checkpoint is readable by h5dump" "no h5dump"
fi

KILLED=$W/killed
if start_and_wait_for_checkpoint "$KILLED"; then
    kill -KILL "$BG_PID" 2>/dev/null || true
    wait "$BG_PID" 2>/dev/null || true
    grit run "$DEMO" --restart "$KILLED" "${DEMO_SET[@]}"
    if [[ $RC -eq 0 ]] && why=$(same_outputs "$STRAIGHT" "$KILLED"); then
        pass "SIGKILL mid-run, --restart DIR: series, impacts, crater, pvd and snapshots identical to the straight run"
    else
        fail "SIGKILL mid-run, --restart DIR: outputs identical to the straight run" "exit $RC; $why; $(cat "$W/stderr")"
    fi
    if [[ -n $JSON_PY ]] && "$JSON_PY" -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if "checkpoint_" in (j["restarted_from"] or "") else 1)' "$KILLED/summary.json"; then
        pass "summary.json of a restarted run names its checkpoint (restarted_from)"
    else
        fail "summary.json of a restarted run names its checkpoint (restarted_from)"
    fi
else
    fail "SIGKILL mid-run: a checkpoint appeared" "none within 30 s"
fi

INTERRUPTED=$W/interrupted
if start_and_wait_for_checkpoint "$INTERRUPTED"; then
    kill -INT "$BG_PID" 2>/dev/null || true
    bg_rc=0
    wait "$BG_PID" || bg_rc=$?
    status=""
    [[ -n $JSON_PY ]] && status=$("$JSON_PY" -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$INTERRUPTED/summary.json" 2>/dev/null || true)
    if [[ $bg_rc -eq 130 && $status == interrupted ]]; then
        pass "SIGINT: exit 130, summary.json status 'interrupted'"
    elif [[ $bg_rc -eq 0 ]]; then
        skip "SIGINT: exit 130" "the run finished before the signal arrived"
    else
        fail "SIGINT: exit 130, summary.json status 'interrupted'" "exit $bg_rc, status '$status'; $(cat "$W/bg_err")"
    fi
    latest=$(ls "$INTERRUPTED"/checkpoints/checkpoint_*.h5 | tail -n 1)
    grit run "$DEMO" --restart "$latest" "${DEMO_SET[@]}"
    if [[ $RC -eq 0 ]] && why=$(same_outputs "$STRAIGHT" "$INTERRUPTED"); then
        pass "SIGINT, --restart FILE: outputs identical to the straight run"
    else
        fail "SIGINT, --restart FILE: outputs identical to the straight run" "exit $RC; $why; $(cat "$W/stderr")"
    fi
else
    fail "SIGINT mid-run: a checkpoint appeared" "none within 30 s"
fi

# A restart applies the checkpointed run's --set again: restarted with none of its own (the demo's own
# time.end is 5e-4), the killed run still stops at 1.2e-5 with the straight run's outputs.
CARRIED=$W/carried
if start_and_wait_for_checkpoint "$CARRIED"; then
    kill -KILL "$BG_PID" 2>/dev/null || true
    wait "$BG_PID" 2>/dev/null || true
    grit run "$DEMO" --restart "$CARRIED" --threads 2
    if [[ $RC -eq 0 ]] && why=$(same_outputs "$STRAIGHT" "$CARRIED") &&
        grep -q "the checkpointed run's --set apply first: time.end=1.2e-5" "$W/stderr"; then
        pass "--restart without --set: the checkpointed run's --set apply, outputs identical to the straight run"
    else
        fail "--restart without --set: the checkpointed run's --set apply" "exit $RC; $why; $(cat "$W/stderr")"
    fi
else
    fail "SIGKILL mid-run (carried --set): a checkpoint appeared" "none within 30 s"
fi

# SIGUSR1 (what a batch system sends ahead of its time limit): a checkpoint, exit 138, and the restart
# continues bit for bit.
USR1=$W/usr1
if start_and_wait_for_checkpoint "$USR1"; then
    kill -USR1 "$BG_PID" 2>/dev/null || true
    bg_rc=0
    wait "$BG_PID" || bg_rc=$?
    if [[ $bg_rc -eq 138 ]] && grep -q 'interrupted by signal 10' "$W/bg_err"; then
        pass "SIGUSR1: a checkpoint and exit 138"
    elif [[ $bg_rc -eq 0 ]]; then
        skip "SIGUSR1: exit 138" "the run finished before the signal arrived"
    else
        fail "SIGUSR1: a checkpoint and exit 138" "exit $bg_rc; $(cat "$W/bg_err")"
    fi
    grit run "$DEMO" --restart "$USR1" "${DEMO_SET[@]}"
    if [[ $RC -eq 0 ]] && why=$(same_outputs "$STRAIGHT" "$USR1"); then
        pass "SIGUSR1, --restart DIR: outputs identical to the straight run"
    else
        fail "SIGUSR1, --restart DIR: outputs identical to the straight run" "exit $RC; $why; $(cat "$W/stderr")"
    fi
else
    fail "SIGUSR1 mid-run: a checkpoint appeared" "none within 30 s"
fi

# --max-wall-time: a checkpoint and a planned stop (exit 0, status 'interrupted'); the restart finishes
# the run bit for bit.
WALL=$W/wall
grit run "$DEMO" --out "$WALL" "${DEMO_SET[@]}" --set output.checkpoint_interval=0 --max-wall-time 0:01
wall_status=$("${JSON_PY:-python3}" -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$WALL/summary.json" 2>/dev/null || true)
if [[ $RC -eq 0 && $wall_status == completed ]]; then
    skip "--max-wall-time 0:01 stops the run" "the run finished within a second"
elif [[ $RC -eq 0 && $wall_status == interrupted ]] && grep -q 'wall-time limit' "$W/stderr" &&
    compgen -G "$WALL/checkpoints/checkpoint_*.h5" >/dev/null; then
    pass "--max-wall-time 0:01: a checkpoint, exit 0, status 'interrupted'"
    grit run "$DEMO" --restart "$WALL" "${DEMO_SET[@]}" --set output.checkpoint_interval=0
    if [[ $RC -eq 0 ]] && why=$(same_outputs "$STRAIGHT" "$WALL"); then
        pass "--max-wall-time, --restart DIR: outputs identical to the straight run"
    else
        fail "--max-wall-time, --restart DIR: outputs identical to the straight run" "exit $RC; $why; $(cat "$W/stderr")"
    fi
else
    fail "--max-wall-time 0:01: a checkpoint, exit 0, status 'interrupted'" "exit $RC, status '$wall_status': $(cat "$W/stderr")"
fi
grit run "$DEMO" --out "$W/wall_bad" --max-wall-time 1:xx
if [[ $RC -eq 2 ]] && grep -q -- '--max-wall-time 1:xx: ' "$W/stderr"; then
    pass "--max-wall-time 1:xx refused: $(cat "$W/stderr")"
else
    fail "--max-wall-time 1:xx refused" "exit $RC: $(cat "$W/stderr")"
fi

# A case with no timed checkpoints still has one on wall time (output.checkpoint_wall_interval, 30 min by
# default; 0.3 s here): killed without warning, it loses at most that, and continues bit for bit.
WALLCK=$W/wall_checkpoint
if start_and_wait_for_checkpoint "$WALLCK" --set output.checkpoint_interval=0 --set output.checkpoint_wall_interval=0.3; then
    kill -KILL "$BG_PID" 2>/dev/null || true
    wait "$BG_PID" 2>/dev/null || true
    grit run "$DEMO" --restart "$WALLCK" "${DEMO_SET[@]}" --set output.checkpoint_interval=0
    if [[ $RC -eq 0 ]] && why=$(same_outputs "$STRAIGHT" "$WALLCK") && ! compgen -G "$WALLCK/checkpoints/.*.tmp" >/dev/null; then
        pass "wall-time checkpoint, SIGKILL, --restart DIR: outputs identical to the straight run"
    else
        fail "wall-time checkpoint, SIGKILL, --restart DIR: outputs identical to the straight run" "exit $RC; $why; $(cat "$W/stderr")"
    fi
else
    fail "output.checkpoint_wall_interval=0.3: a checkpoint appeared" "none within 30 s"
fi

# A file-size limit (EFBIG, as a full disk's ENOSPC) while a checkpoint is written: a clear error, no
# temporary left, and the checkpoint before it intact (the run continues from it bit for bit).
FULL=$W/full
cp -r -- "$STRAIGHT" "$FULL"
full_rc=0
( trap '' XFSZ; ulimit -f 64; exec "$GRIT" run "$DEMO" --restart "$FULL" "${DEMO_SET[@]}" --set output.snapshots=false \
    --set time.end=1.4e-5 ) >"$W/stdout" 2>"$W/stderr" || full_rc=$?
if [[ $full_rc -ne 0 && $full_rc -ne 2 ]] && grep -q 'cannot write the checkpoint' "$W/stderr" &&
    grep -q 'intact' "$W/stderr" && ! compgen -G "$FULL/checkpoints/.*.tmp" >/dev/null; then
    pass "a checkpoint that cannot be written (file-size limit): a clear error, no temporary left: $(cat "$W/stderr")"
else
    fail "a checkpoint that cannot be written (file-size limit): a clear error" "exit $full_rc: $(cat "$W/stderr")"
fi

# A finished run extended with --set time.end: rows continue, none repeated.
grit run "$DEMO" --restart "$STRAIGHT" "${DEMO_SET[@]}" --set time.end=1.4e-5
if [[ $RC -eq 0 ]] && "${JSON_PY:-python3}" - "$STRAIGHT/series.csv" <<'PYEOF'
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
t = [float(r[0]) for r in rows]
sys.exit(0 if all(b > a for a, b in zip(t, t[1:])) and abs(t[-1] - 1.4e-5) < 1e-12 else 1)
PYEOF
then
    pass "--restart a finished run with --set time.end=1.4e-5: series continues to 1.4e-5 without repeated rows"
else
    fail "--restart a finished run with --set time.end: series continues without repeated rows" "exit $RC; $(cat "$W/stderr")"
fi

# The run whose checkpoint could not be written (above) continues from the checkpoint before it, as the
# straight run extended to 1.4e-5 did.
grit run "$DEMO" --restart "$FULL" "${DEMO_SET[@]}" --set time.end=1.4e-5
if [[ $RC -eq 0 ]] && cmp -s "$FULL/series.csv" "$STRAIGHT/series.csv"; then
    pass "after the failed checkpoint the run continues from the one before it: series.csv identical"
else
    fail "after the failed checkpoint the run continues from the one before it" "exit $RC: $(cat "$W/stderr")"
fi

# summary.json sums the run's segments; a restart with nothing left to run says so and changes nothing.
if "${JSON_PY:-python3}" -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if j["segments"] == 2 and j["wall_time_s"] > j["segment_wall_time_s"] > 0 else 1)' "$STRAIGHT/summary.json"; then
    pass "summary.json of an extended run sums its segments (segments 2, wall_time_s over both)"
else
    fail "summary.json of an extended run sums its segments" "$(grep -E 'segment|wall_time' "$STRAIGHT/summary.json")"
fi
cp -- "$STRAIGHT/summary.json" "$W/summary_before.json"
grit run "$DEMO" --restart "$STRAIGHT" "${DEMO_SET[@]}" --set time.end=1.4e-5
if [[ $RC -eq 0 ]] && grep -q 'already at time.end' "$W/stderr" && cmp -s "$STRAIGHT/summary.json" "$W/summary_before.json"; then
    pass "--restart a run already at time.end: says so, summary.json's totals kept: $(cat "$W/stderr")"
else
    fail "--restart a run already at time.end: says so, summary.json's totals kept" "exit $RC: $(cat "$W/stderr")"
fi

# A fresh run into a folder that holds a run is refused (exit 2, naming --restart and --overwrite) and
# changes nothing; with --overwrite it replaces the run and its derived files (plots), not other files.
REPLACED=$W/replaced
cp -r -- "$STRAIGHT" "$REPLACED"
mkdir -p "$REPLACED/plots" && touch "$REPLACED/plots/crater_profile.png" "$REPLACED/notes.txt"
stamp=$(stat -c %Y "$REPLACED/summary.json")
grit run "$DEMO" --out "$REPLACED" "${DEMO_SET[@]}"
if [[ $RC -eq 2 ]] && grep -q "the folder holds a completed run of case 'demo'" "$W/stderr" &&
    grep -q -- '--restart' "$W/stderr" && grep -q -- '--overwrite' "$W/stderr" &&
    [[ $(stat -c %Y "$REPLACED/summary.json") -eq $stamp && -e $REPLACED/plots/crater_profile.png ]]; then
    pass "a fresh run into a folder that holds a run is refused, nothing touched: $(cat "$W/stderr")"
else
    fail "a fresh run into a folder that holds a run is refused" "exit $RC: $(cat "$W/stderr")"
fi
grit run "$DEMO" --out "$REPLACED" "${DEMO_SET[@]}" --overwrite
if [[ $RC -eq 0 && ! -e $REPLACED/plots && -f $REPLACED/notes.txt ]] &&
    [[ $(tail -n 1 "$REPLACED/series.csv" | cut -d, -f1) == 1.2e-05 ]]; then
    pass "--overwrite replaces the run (series to 1.2e-5 again) and its plots, keeps other files"
else
    fail "--overwrite replaces the run and its plots, keeps other files" "exit $RC: $(cat "$W/stderr"); $(ls "$REPLACED")"
fi
grit run "$DEMO" --restart "$REPLACED" --overwrite
if [[ $RC -eq 2 ]] && grep -q -- '--overwrite: a restart continues' "$W/stderr"; then
    pass "--restart with --overwrite refused: $(cat "$W/stderr")"
else
    fail "--restart with --overwrite refused" "exit $RC: $(cat "$W/stderr")"
fi
touch "$W/a_file"
grit run "$HYDRO" --end-time 0 --out "$W/a_file/run"
if [[ $RC -eq 2 ]] && grep -q -- "--out $W/a_file/run: cannot create the folder" "$W/stderr"; then
    pass "an output folder that cannot be made is refused before the run: $(cat "$W/stderr")"
else
    fail "an output folder that cannot be made is refused before the run" "exit $RC: $(cat "$W/stderr")"
fi

# A run started by an older grit, whose series.csv lacks a column added since, continues: the column is
# added, nan in the rows before the restart.
OLDER=$W/older
cp -r "$STRAIGHT" "$OLDER"
"${JSON_PY:-python3}" - "$OLDER/series.csv" <<'PYEOF'
import sys
lines = open(sys.argv[1]).read().splitlines()
k = lines[0].split(",").index("crater_lip_height")
open(sys.argv[1], "w").write("".join(",".join(f for j, f in enumerate(l.split(",")) if j != k) + "\n" for l in lines))
PYEOF
older_rows=$(($(wc -l < "$OLDER/series.csv") - 1))
grit run "$DEMO" --restart "$OLDER" "${DEMO_SET[@]}" --set time.end=1.6e-5
if [[ $RC -eq 0 ]] && grep -q "series.csv gains column(s) crater_lip_height" "$OLDER/run.log" &&
    [[ $(head -n 1 "$OLDER/series.csv") == $(head -n 1 "$STRAIGHT/series.csv") ]] &&
    "${JSON_PY:-python3}" - "$OLDER/series.csv" "$older_rows" <<'PYEOF'
import math, sys
lines = open(sys.argv[1]).read().splitlines()
k = lines[0].split(",").index("crater_lip_height")
rows = [[float(v) for v in l.split(",")] for l in lines[1:]]
old = int(sys.argv[2])
sys.exit(0 if len(rows) > old and all(math.isnan(r[k]) for r in rows[:old])
         and not any(math.isnan(r[k]) for r in rows[old:]) else 1)
PYEOF
then
    pass "--restart a run whose series.csv lacks a newer column: the column is added, nan before the restart"
else
    fail "--restart a run whose series.csv lacks a newer column" "exit $RC; $(cat "$W/stderr")"
fi

# Checkpoints that do not fit: exit 2, one line.
expect_restart_error() {
    local name=$1 pattern=$2
    shift 2
    grit run "$@" --quiet
    local lines
    lines=$(grep -c '' "$W/stderr" || true)
    if [[ $RC -eq 2 && $lines -eq 1 ]] && grep -qF -- "$pattern" "$W/stderr"; then
        pass "restart refused: $name -> exit 2: $(cat "$W/stderr")"
    else
        fail "restart refused: $name" "exit $RC, $lines line(s): $(cat "$W/stderr")"
    fi
}
ckpts=("$STRAIGHT"/checkpoints/checkpoint_*.h5)  # the extension above wrote newer ones
expect_restart_error "no such folder" "no such checkpoint" "$DEMO" --restart "$W/nowhere"
expect_restart_error "another case's checkpoint" "written by case 'demo'" "$HYDRO" --restart "${ckpts[-1]}"
expect_restart_error "another particle spacing" "numerics.particle_spacing" "$DEMO" --restart "$STRAIGHT" \
    --set numerics.particle_spacing=2e-4
cp -- "${ckpts[-1]}" "$W/truncated.h5"
truncate -s 2000 "$W/truncated.h5"
expect_restart_error "a truncated checkpoint" "truncated.h5" "$DEMO" --restart "$W/truncated.h5"

# --- run estimates ----------------------------------------------------------------------------------------
grit check "$ROOT/cases/demo.toml"
if [[ $RC -eq 0 ]] && grep -Eq '^estimate: ~[0-9.e+]+ steps, ~[0-9.e+]+ particles, [0-9]+ outputs' "$W/stdout"; then
    pass "check prints the estimate: $(grep estimate "$W/stdout")"
else
    fail "check prints the estimate" "exit $RC: $(cat "$W/stdout" "$W/stderr")"
fi
grit check "$ROOT/cases/demo.toml" --set time.end=10
if [[ $RC -eq 2 ]] && grep -q "key 'time.end' = 10:" "$W/stderr" && grep -q 'output.max_outputs' "$W/stderr"; then
    pass "a time.end in the wrong unit is refused: $(cat "$W/stderr")"
else
    fail "a time.end in the wrong unit is refused" "exit $RC: $(cat "$W/stderr")"
fi

# --- sweep and plot -------------------------------------------------------------------------------------
AWJ=$ROOT/cases/awj_aluminium_2d/case.toml
PLAIN_EQ35=materials.Al6061_T6.failure_surface_triaxiality=1e9
SWEEP=$W/sweep
grit sweep "$AWJ" --param jet.pressure=1.5e8,2.5e8 --set time.end=4e-6 --set output.snapshots=false \
    --jobs 2 --threads 2 --out "$SWEEP"
rows=$(grep -c ',completed,' "$SWEEP/sweep.csv" 2>/dev/null || true)
if [[ $RC -eq 0 && $rows -eq 2 ]] && head -1 "$SWEEP/sweep.csv" | grep -q '^jet.pressure,crater_depth,crater_width,eroded_mass,' &&
    head -1 "$SWEEP/sweep.csv" | grep -q ',particle_spacing,crater_depth_resolved,status,folder$' &&
    [[ $(grep -c ',below one spacing,completed,' "$SWEEP/sweep.csv") -eq 2 ]] &&
    [[ -f "$SWEEP/jet.pressure=2.5e8/summary.json" ]]; then
    pass "sweep: two runs, sweep.csv with the swept key and the results"
else
    fail "sweep: two runs, sweep.csv with the swept key and the results" "exit $RC, $rows completed rows: $(cat "$W/stderr")"
fi
stamp=$(stat -c %Y "$SWEEP/jet.pressure=2.5e8/summary.json")
grit sweep "$AWJ" --param jet.pressure=1.5e8,2.5e8 --set time.end=4e-6 --set output.snapshots=false --out "$SWEEP"
if [[ $RC -eq 0 && $(grep -c 'done before, kept' "$W/stdout") -eq 2 &&
    $(stat -c %Y "$SWEEP/jet.pressure=2.5e8/summary.json") -eq $stamp ]]; then
    pass "sweep: finished runs are not redone"
else
    fail "sweep: finished runs are not redone" "exit $RC: $(cat "$W/stdout")"
fi
# The same sweep folder with another --set: the kept runs were of other settings, so they run again.
grit sweep "$AWJ" --param jet.pressure=1.5e8,2.5e8 --set time.end=5e-6 --set output.snapshots=false --out "$SWEEP"
if [[ $RC -eq 0 && $(grep -c 'done before with other --set' "$W/stdout") -eq 2 ]] &&
    "${JSON_PY:-python3}" -c 'import json,sys; sys.exit(0 if abs(json.load(open(sys.argv[1]))["end_time"] - 5e-6) < 1e-12 else 1)' \
        "$SWEEP/jet.pressure=2.5e8/summary.json"; then
    pass "sweep: runs done before with other --set run again"
else
    fail "sweep: runs done before with other --set run again" "exit $RC: $(cat "$W/stdout")"
fi
grit sweep "$AWJ" --param jet.pressure=150 --out "$W/badsweep"
if [[ $RC -eq 2 ]] && grep -q "key 'jet.pressure' = 150" "$W/stderr" && [[ ! -e "$W/badsweep" ]]; then
    pass "sweep: a bad value stops it before any run: $(cat "$W/stderr")"
else
    fail "sweep: a bad value stops it before any run" "exit $RC: $(cat "$W/stderr")"
fi
grit crater "$SWEEP"
if [[ $RC -eq 0 && $(grep -c 'outputs measured' "$W/stdout") -eq 2 && -s "$SWEEP/jet.pressure=1.5e8/crater_measures.csv" &&
    -s "$SWEEP/jet.pressure=2.5e8/crater_measures.csv" ]]; then
    pass "crater: a sweep folder: each run measured again"
else
    fail "crater: a sweep folder: each run measured again" "exit $RC: $(cat "$W/stdout") $(cat "$W/stderr")"
fi
if [[ -n $JSON_PY ]] && "$JSON_PY" -c 'import matplotlib, numpy' >/dev/null 2>&1; then
    grit plot "$SWEEP"
    if [[ $RC -eq 0 && -s "$SWEEP/plots/sweep_jet.pressure.png" && -s "$SWEEP/plots/sweep_history.png" ]]; then
        pass "plot: a sweep folder gives C_d, C_w against the swept key, and each run's against time"
    else
        fail "plot: a sweep folder" "exit $RC: $(cat "$W/stderr")"
    fi
    # With eq. (35)'s surface bound off, the water hammer fails aluminium's top row within 6 us: a run with
    # removals in seconds (docs/validation.md, "The surface's triaxiality").
    grit run "$AWJ" --out "$W/awjrun" --set time.end=8e-6 --set "$PLAIN_EQ35" --quiet
    grit plot "$W/awjrun"
    if [[ $RC -eq 0 && -s "$W/awjrun/plots/crater_size.png" && -s "$W/awjrun/plots/crater_profile.png" &&
        -s "$W/awjrun/plots/impacts.png" && -s "$W/awjrun/plots/erosion.png" ]]; then
        pass "plot: a run folder gives the crater profile and size, eroded mass, impact histograms and erosion map"
    else
        fail "plot: a run folder" "exit $RC: $(cat "$W/stderr") $(ls "$W/awjrun/plots" 2>&1)"
    fi
    # The water hammer at 400 m/s damages the sandstone within half a microsecond of landing (3.6 us).
    grit run "$ROOT/cases/waterjet_sandstone_2d/case.toml" --out "$W/rockrun" --set "inlet[0].velocity=400" \
        --set time.end=5e-6 --quiet
    grit plot "$W/rockrun"
    if [[ $RC -eq 0 && -s "$W/rockrun/plots/damage.png" ]] && grep -q 'damage.png' "$W/stdout"; then
        pass "plot: a rock's run gives the damage map at its outputs"
    else
        fail "plot: a rock's run gives the damage map" "exit $RC: $(cat "$W/stderr") $(ls "$W/rockrun/plots" 2>&1)"
    fi
    # 3D: the crater is a map over x and y (crater.csv x,y,surface,time); the first grain dents the
    # copper at about 4 us.
    grit run "$ROOT/cases/awj_copper_3d/case.toml" --out "$W/awj3d" --set time.end=5e-6 --set output.snapshots=false \
        --quiet
    grit plot "$W/awj3d"
    if [[ $RC -eq 0 && -s "$W/awj3d/plots/crater_map.png" && -s "$W/awj3d/plots/crater_profile.png" ]] &&
        [[ $(head -1 "$W/awj3d/crater.csv") == x,y,surface,time ]] && grep -q '"crater_length"' "$W/awj3d/summary.json"; then
        pass "plot: a 3D run gives the crater map and the section through its deepest cell"
    else
        fail "plot: a 3D run gives the crater map" "exit $RC: $(cat "$W/stderr") $(ls "$W/awj3d/plots" 2>&1)"
    fi
    if remeasure_matches_series "$W/awj3d" 1; then
        pass "crater: a 3D run's map measured again from crater_history.csv gives series.csv's crater columns at every output"
    else
        fail "crater: a 3D run measured again from crater_history.csv" "exit $RC: $(cat "$W/stderr") $(cat "$W/stdout")"
    fi
    grit run "$ROOT/cases/dambreak_2d/case.toml" --out "$W/waterrun" --set time.end=2e-3 --quiet
    grit plot "$W/waterrun"
    if [[ $RC -eq 0 && -s "$W/waterrun/plots/snapshot.png" && ! -e "$W/waterrun/plots/damage.png" ]]; then
        pass "plot: a run without a solid gives its snapshot and no damage map"
    else
        fail "plot: a run without a solid" "exit $RC: $(cat "$W/stderr") $(ls "$W/waterrun/plots" 2>&1)"
    fi
else
    skip "plot" "no python3 with matplotlib and numpy"
fi

# --- scripts/impact_summary.py: impacts of deflected grains against the others ------------------------------
mkdir -p "$W/impsum"
printf 'time,grain,target,speed,angle,x,y,grain_collisions\n%s\n%s\n%s\n%s\n' \
    '1e-5,0,copper,200,90,1e-3,0,1' '2e-5,1,copper,100,60,-1e-3,0,2' '3e-5,2,copper,300,80,1e-4,0,0' \
    '4e-5,3,copper,250,70,-2e-4,0,0' > "$W/impsum/impacts.csv"
if [[ -z $JSON_PY ]]; then
    skip "impact_summary.py" "no python3"
elif out=$("$JSON_PY" "$ROOT/scripts/impact_summary.py" "$W/impsum" 2>&1) &&
    grep -q 'target copper: 4 impacts, 2 (50 %) by grains that had met another grain' <<<"$out" &&
    grep -q 'met a grain before: *2 | |x| median 1 mm, 90 % within 1 mm | speed 150 m/s' <<<"$out" &&
    grep -q 'met none: *2 | |x| median 0.15 mm' <<<"$out"; then
    pass "impact_summary.py: splits the impacts by grain_collisions, with where they landed"
else
    fail "impact_summary.py: splits the impacts by grain_collisions" "$out"
fi
printf 'time,grain,target,speed,angle,x,y\n1e-5,0,copper,200,90,1e-3,0\n' > "$W/impsum/impacts.csv"
if [[ -n $JSON_PY ]]; then
    if ! out=$("$JSON_PY" "$ROOT/scripts/impact_summary.py" "$W/impsum" 2>&1) &&
        grep -q 'no grain_collisions column' <<<"$out"; then
        pass "impact_summary.py: an impacts.csv without grain_collisions is refused: $out"
    else
        fail "impact_summary.py: an impacts.csv without grain_collisions is refused" "$out"
    fi
fi

# --- eroded.csv: every removed solid particle, summing to the eroded mass; --dump-from -------------------
grit run "$AWJ" --out "$W/eroded" --set time.end=6e-6 --set output.snapshots=false --threads 1 --set "$PLAIN_EQ35" \
    --quiet
if [[ -n $JSON_PY ]] && [[ $RC -eq 0 ]] && why=$("$JSON_PY" - "$W/eroded" <<'PYEOF'
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/eroded.csv")))
header = open(d + "/eroded.csv").readline().strip()
summary = json.load(open(d + "/summary.json"))
eroded = summary["eroded_mass"]
total = sum(float(r["mass"]) for r in rows)
# first_removal_time: the first row's time (eroded.csv writes 9 digits)
first = summary.get("first_removal_time")
ok = (header.startswith("time,id,material,cause,x,y,mass,plastic_strain,damage,pressure,von_mises,triaxiality")
      and len(rows) > 0 and abs(total - eroded) <= 1e-9 * eroded
      and first is not None and abs(first - min(float(r["time"]) for r in rows)) <= 1e-8 * first
      and all(r["cause"] == "failed" and float(r["damage"]) >= 1.0 and r["material"] == "Al6061_T6" for r in rows)
      and header.endswith(",speed,surface") and all(r["surface"] == "1" for r in rows))  # the hammered top row
print(f"{len(rows)} rows, {total:.6g} kg/m against eroded_mass {eroded:.6g}, the first at {first} s")
sys.exit(0 if ok else 1)
PYEOF
); then
    pass "eroded.csv: one row per removed particle, failed at D = 1, summing to eroded_mass, the first at summary.json's first_removal_time ($why)"
else
    fail "eroded.csv: one row per removed particle, summing to eroded_mass" "exit $RC; ${why:-}; $(head -n 3 "$W/eroded/eroded.csv" 2>&1)"
fi
if remeasure_matches_series "$W/eroded" 1; then
    pass "crater: a 2D run measured again from crater_history.csv gives series.csv's crater columns at every output"
else
    fail "crater: a 2D run measured again from crater_history.csv" "exit $RC: $(cat "$W/stderr") $(cat "$W/stdout")"
fi
grit crater "$T0"
if [[ $RC -eq 2 ]] && grep -q "summary.json: no crater_region: the run had no \[crater\]" "$W/stderr"; then
    pass "crater: a run without [crater]: exit 2, naming summary.json"
else
    fail "crater: a run without [crater]: exit 2" "exit $RC: $(cat "$W/stderr")"
fi
grit crater "$W/no_such_run"
if [[ $RC -eq 2 ]] && grep -q "no_such_run/summary.json: cannot be read" "$W/stderr"; then
    pass "crater: a folder that is not a run: exit 2, naming the file"
else
    fail "crater: a folder that is not a run: exit 2" "exit $RC: $(cat "$W/stderr")"
fi
# scripts/crater_windows.py: the mean of each window (a, b] over the outputs with a crater, and the eroded
# mass at the window's last output, against series.csv read here (outputs every microsecond to 6 us).
if [[ -n $JSON_PY ]]; then
    if out=$("$JSON_PY" "$ROOT/scripts/crater_windows.py" "$W/eroded" --edges 0,0.003,0.006 \
        --columns crater_depth,crater_shape_factor 2>&1) && why=$("$JSON_PY" - "$W/eroded/series.csv" "$out" <<'PYEOF'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
def mean(col, a, b, scale):
    v = [float(r[col]) * scale for r in rows if a < float(r["time"]) <= b and math.isfinite(float(r[col]))]
    return v and sum(v) / len(v)
want = []
for col, scale, fmt in (("crater_depth", 1e3, "{:.3f}"), ("crater_shape_factor", 1.0, "{:.3g}")):
    cells = [mean(col, a, b, scale) for a, b in ((0, 3e-6), (3e-6, 6e-6))]
    want.append("| eroded | " + " | ".join("-" if c == [] else fmt.format(c) for c in cells) + " |")
last = [max((r for r in rows if a < float(r["time"]) <= b), key=lambda r: float(r["time"])) for a, b in ((0, 3e-6), (3e-6, 6e-6))]
want.append("| eroded | " + " | ".join("{:.3g}".format(float(r["eroded_mass"]) * 1e3) for r in last) + " |")
lines = sys.argv[2].splitlines()
missing = [w for w in want if w not in lines]
print("; ".join(missing) if missing else " / ".join(want))
sys.exit(1 if missing else 0)
PYEOF
); then
        pass "crater_windows.py: window means of C_d and the shape factor, the eroded mass at each window's end ($why)"
    else
        fail "crater_windows.py: window means against series.csv" "${why:-}; $out"
    fi
    rc=0
    out=$("$JSON_PY" "$ROOT/scripts/crater_windows.py" "$W/no_such_run" 2>&1) || rc=$?
    if [[ $rc -eq 2 && $out == *"no_such_run: no series.csv"* ]]; then
        pass "crater_windows.py: a folder that is not a run: exit 2, naming it"
    else
        fail "crater_windows.py: a folder that is not a run: exit 2" "$out"
    fi
fi
# A solid block pushed into an outlet: what the outlet takes of it is eroded mass, logged as "outlet".
mkdir -p "$W/outletcase"
cat > "$W/outletcase/case.toml" <<'EOF'
[simulation]
dimension = 2
[time]
end = 2.0e-6
[output]
interval = 1.0e-6
snapshots = false
[numerics]
particle_spacing = 1.0e-4
[[solid]]
shape = "box"
min = [0.0, 0.0]
max = [1.0e-3, 1.0e-3]
material = "OFHC_copper"
velocity = [100.0, 0.0]
[[outlet]]
min = [1.1e-3, -1.0e-3]
max = [3.0e-3, 2.0e-3]
[domain]
min = [-1.0e-3, -1.0e-3]
max = [3.0e-3, 2.0e-3]
EOF
grit run "$W/outletcase/case.toml" --out "$W/outlet" --threads 1 --quiet
if [[ -n $JSON_PY ]] && [[ $RC -eq 0 ]] && why=$("$JSON_PY" - "$W/outlet" <<'PYEOF'
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/eroded.csv")))
summary = json.load(open(d + "/summary.json"))
eroded = summary["eroded_mass"]
total = sum(float(r["mass"]) for r in rows)
first = summary.get("first_removal_time")
# 0.2 mm of travel takes the block's front column (x = 0.95 mm) past x = 1.1 mm: 10 particles
ok = (len(rows) == 10 and all(r["cause"] == "outlet" and float(r["x"]) >= 1.1e-3 for r in rows)
      and eroded > 0.0 and abs(total - eroded) <= 1e-9 * eroded
      and first is not None and abs(first - min(float(r["time"]) for r in rows)) <= 1e-8 * first)
print(f"{len(rows)} rows, {total:.6g} kg/m against eroded_mass {eroded:.6g}")
sys.exit(0 if ok else 1)
PYEOF
); then
    pass "eroded.csv: solid taken by an outlet before it failed is logged as 'outlet' ($why)"
else
    fail "eroded.csv: solid taken by an outlet is logged" "exit $RC; ${why:-}; $(head -n 3 "$W/outlet/eroded.csv" 2>&1)"
fi
grit run "$HYDRO" --out "$W/dump" --set time.end=2e-3 --set output.snapshots=false --dump-from 3 --quiet
steps=$(grep -o '"steps": *[0-9]*' "$W/dump/summary.json" 2>/dev/null | grep -o '[0-9]*$' || echo 0)
dumps=$(find "$W/dump/dump" -name 'hydrostatic_2d_step_*.vtu' 2>/dev/null | wc -l)
if [[ $RC -eq 0 && $steps -ge 3 && $dumps -eq $((steps - 2)) && -s "$W/dump/dump/hydrostatic_2d_step_000000003.vtu" ]]; then
    pass "--dump-from 3: the particles of every step from step 3 on ($dumps of $steps steps)"
else
    fail "--dump-from 3: the particles of every step from step 3 on" "exit $RC, $dumps files, $steps steps: $(cat "$W/stderr")"
fi
grit run "$HYDRO" --out "$W/dump0" --dump-from 0
if [[ $RC -eq 2 ]] && grep -q -- "--dump-from 0" "$W/stderr"; then
    pass "--dump-from 0 is refused: $(cat "$W/stderr")"
else
    fail "--dump-from 0 is refused" "exit $RC: $(cat "$W/stderr")"
fi

# --- summary --------------------------------------------------------------------------------------------

echo "$passed passed, $failed failed"
if [[ $failed -ne 0 ]]; then
    printf 'failed: %s\n' "${failures[@]}"
    exit 1
fi
