"""The house rules of docs/architecture.md, read off the code: which folder may import
which, no circles, click and rich only where text meets a terminal.

Every import counts, at the top of a module or inside a function (a lazy import is
still a dependency) or under TYPE_CHECKING.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from conftest import ROOT

PACKAGE = ROOT / "rbdsolve"

# Each layer may import itself and the layers it names here; nothing else of rbdsolve.
# The order is the pipeline's: problem -> model -> solvers -> report -> render -> cli,
# with the vocabulary (report) and the exam form (form) on the ground floor.
ALLOWED = {
    "errors": set(),
    "form": set(),
    "problem": {"errors"},
    "model": {"problem", "report", "form", "errors"},
    "report": {"form", "errors"},
    "solvers": {"model", "problem", "report", "form", "errors"},
    "render": {"solvers", "model", "problem", "report", "form", "errors"},
    "teaching": {"render", "solvers", "model", "problem", "report", "form", "errors"},
    "cli": {"teaching", "render", "solvers", "model", "problem", "report", "form", "errors", "package"},
    "api": {"teaching", "render", "solvers", "model", "problem", "report", "form", "errors"},
    "package": set(),  # rbdsolve/__init__.py, __main__.py: see PACKAGE_FILES
}
PACKAGE_FILES = {"__main__": {"cli"}, "__init__": {"api"}}  # __init__: the API, lazily
# The solvers' machinery: folders of solvers/ that are no family. They import no family;
# a family imports them and the layers below, and only the families FAMILY_USES names.
MACHINERY = {"conditions", "configuration", "lagrange", "numeric", "routes"}
FAMILY_USES = {"modes": {"equilibria"}, "steady_spin": {"inertia"}, "reactions": {"eom"}, "energy": {"reactions"},
               "equilibria": {"reactions"}}  # where a contact would pull at an equilibrium: Newton–Euler at rest
TERMINAL_LIBRARIES = {"click", "rich"}
MAY_PRINT = {"cli", "render"}


def module_name(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def imports(path: Path) -> set[str]:
    """Every module named by an import in ``path`` (absolute imports only: the house
    uses no relative ones)."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            assert node.level == 0, f"{path}: relative import"
            submodules = {f"{node.module}.{a.name}" for a in node.names} & MODULES.keys()
            found |= submodules  # ``from rbdsolve.problem import expr``: the module expr
            if len(submodules) < len(node.names):
                found.add(node.module)
    return found


def layer(module: str) -> str:
    parts = module.split(".")
    if len(parts) == 1 or parts[1] in PACKAGE_FILES:
        return "package"
    return parts[1]


def internal(module: str) -> str | None:
    """The rbdsolve module an import names (a name inside a module: the module)."""
    while module and module not in MODULES:
        module = module.rpartition(".")[0]
    return module or None


GRAPH = {m: {t for t in map(internal, imports(p)) if t and t != m} for m, p in MODULES.items()}


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_run_one_way(module: str) -> None:
    mine = layer(module)
    file = module.rpartition(".")[2] if "." in module else "__init__"  # rbdsolve itself: its __init__
    allowed = PACKAGE_FILES.get(file, set()) if mine == "package" else ALLOWED[mine]
    assert mine in ALLOWED, f"{module}: a folder docs/architecture.md does not name"
    wrong = sorted(t for t in GRAPH[module] if layer(t) != mine and layer(t) not in allowed)
    assert not wrong, f"{module} ({mine}/) may not import {wrong}: see docs/architecture.md"


def family(module: str) -> str | None:
    parts = module.split(".")
    return parts[2] if len(parts) > 3 and parts[1] == "solvers" else None


@pytest.mark.parametrize("module", sorted(m for m in MODULES if family(m)))
def test_solver_families_stand_apart(module: str) -> None:
    mine = family(module)
    others = {family(t) for t in GRAPH[module] if family(t) and family(t) != mine}
    if mine in MACHINERY:
        assert not others - MACHINERY, (
            f"{module}: the solvers' machinery may not import a family ({others - MACHINERY})")
    else:
        assert others <= FAMILY_USES.get(mine, set()) | MACHINERY, f"{module} imports the families {others}"


def test_no_circles() -> None:
    """No module imports one that imports it back, however far round (Tarjan's
    strongly connected components of the import graph)."""
    index, low, stack, on_stack, circles = {}, {}, [], set(), []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in GRAPH[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                circles.append(sorted(component))

    for v in sorted(GRAPH):
        if v not in index:
            visit(v)
    assert not circles, f"import circles: {circles}"


def test_only_the_cli_and_renderers_touch_the_terminal() -> None:
    offenders = sorted(m for m, p in MODULES.items()
                       if layer(m) not in MAY_PRINT and {i.split(".")[0] for i in imports(p)} & TERMINAL_LIBRARIES)
    assert not offenders, f"click or rich imported outside cli/ and render/: {offenders}"


def test_the_rules_catch_a_backward_import(tmp_path: Path) -> None:
    """The checker itself: a model module that imports a solver is caught."""
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from rbdsolve.solvers.modes.exact import solve\n", encoding="utf-8")
    named = {internal(i) for i in imports(bad)} - {None}
    assert named == {"rbdsolve.solvers.modes.exact"}
    assert layer("rbdsolve.solvers.modes.exact") not in ALLOWED["model"]


def test_the_exact_routes_load_no_numpy() -> None:
    """numpy and scipy (0.5 s of start-up) come only with a numeric route or a drawing."""
    import subprocess
    import sys

    families = sorted({family(m) for m in MODULES if family(m) and family(m) not in MACHINERY})
    code = "; ".join(f"import rbdsolve.solvers.{f}.exact" for f in families)
    code += "; import sys; print(sorted(m for m in ('numpy', 'scipy') if m in sys.modules))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT)}, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"


JUNK_ROOMS = {"shared", "common", "utils", "misc", "helpers"}


def test_every_folder_is_named_for_what_it_holds() -> None:
    """No junk room: a folder's name says what it holds (docs/architecture.md)."""
    folders = sorted({p.parent.relative_to(ROOT) for p in PACKAGE.rglob("*.py")})
    junk = [str(f) for f in folders if f.name in JUNK_ROOMS]
    assert not junk, f"folders named for no content: {junk}"


def test_no_folder_holds_more_than_twenty_modules() -> None:
    """A folder past 20 modules is split into rooms named for what they hold."""
    folders = {p.parent for p in PACKAGE.rglob("*.py")}
    crowded = {str(f.relative_to(ROOT)): n for f in folders if (n := len(list(f.glob("*.py")))) > 20}
    assert not crowded, f"folders of more than 20 modules: {crowded}"
