#!/bin/bash
# `make install` into a temporary prefix: the binary, its scripts, cases, docs and LICENSE land where the
# README says, the installed grit reports its version, and `grit plot` finds the installed script.
# usage: test_install.sh BUILD_DIR
set -u
BUILD=$1
P=$(mktemp -d "${TMPDIR:-/tmp}/grit_install.XXXXXX")
trap 'rm -rf -- "$P"' EXIT
failed=0
check() { if eval "$2"; then echo "PASS: $1"; else echo "FAIL: $1"; failed=1; fi; }

cmake --install "$BUILD" --prefix "$P" >"$P/install.log" 2>&1 || { cat "$P/install.log"; echo "FAIL: cmake --install"; exit 1; }
check "bin/grit is installed and runs" '[[ $("$P/bin/grit" --version) == "grit "* ]]'
for f in share/grit/scripts/grit_plot.py share/grit/scripts/grit_vtu.py share/grit/scripts/debian_python.py share/grit/scripts/plot_series.py \
         share/grit/scripts/paraview_view.py share/grit/cases/demo.toml share/grit/cases/dambreak_2d/case.toml \
         share/doc/grit/README.md share/doc/grit/LICENSE share/doc/grit/CITATION.cff share/doc/grit/theory.md; do
    check "$f" '[[ -f $P/$f ]]'
done
check "installed scripts are executable" '[[ -x $P/share/grit/scripts/plot_series.py ]]'
check "the installed case checks" '"$P/bin/grit" check "$P/share/grit/cases/demo.toml" >/dev/null'
# grit plot on a folder without results: the installed script (marked here, so that the source tree's
# copy cannot pass for it) runs and says so (exit 2).
sed -i 's/^if __name__ == "__main__":/print("installed copy", file=sys.stderr)\n&/' "$P/share/grit/scripts/grit_plot.py"
mkdir -p "$P/empty"
out=$("$P/bin/grit" plot "$P/empty" 2>&1); rc=$?
check "installed grit plot runs its installed script" '[[ $rc -eq 2 && $out == *"installed copy"* && $out == *"neither series.csv"* ]]'
# The Python module, where Debian's python3 finds it under the prefix; `python3 -m grit` is the installed CLI.
site=$(ls -d "$P"/lib/python3.*/dist-packages 2>/dev/null | head -1)
if [[ -n $site ]]; then
    check "the Python module imports from the prefix" \
        '[[ $(cd / && PYTHONPATH=$site /usr/bin/python3 -c "import grit; print(grit.__file__)") == "$site/grit/__init__.py" ]]'
    check "python3 -m grit runs the installed grit" \
        '[[ $(cd / && PYTHONPATH=$site /usr/bin/python3 -m grit --version) == "grit "* ]] &&
         [[ ! -f $site/grit/_build_paths.py ]]'
    check "the installed module runs a case" \
        '[[ $(cd / && PYTHONPATH=$site /usr/bin/python3 -c "import grit; print(grit.run(grit.Case.load(\"$P/share/grit/cases/hydrostatic_2d/case.toml\").set(\"time.end\", 0.01))[\"status\"])") == completed ]]'
fi
exit $failed
