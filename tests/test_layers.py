"""The layer order of CONTRACTS.md: a package imports only packages at its level or below."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "hltl"

# errors → spec, world → skills → motion → perception → grounding → planner → execution → sim
# → sim3d → bus → bench → viz → cli. Packages that do not exist (yet) are simply not checked.
LAYERS: dict[str, float] = {
    "errors": 0,
    "fileio": 0,
    "spec": 1,
    "world": 1,
    "skills": 2,
    "motion": 3,
    "perception": 4,
    "grounding": 4.5,  # produces spec objects; below execution (which does not import it)
    "planner": 5,
    "execution": 6,
    "sim": 7,
    "sim3d": 8,
    "bus": 9,
    "bench": 10,
    "viz": 11,
    "cli": 12,
}


# Known exceptions, each with why it is there and where it should go.
KNOWN: set[tuple[str, str]] = set()


def _package(module: str) -> str | None:
    parts = module.split(".")
    if parts[0] != "hltl" or len(parts) < 2:
        return None
    return parts[1]


def _imports(path: Path) -> list[tuple[int, str]]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out: list[tuple[int, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append((node.lineno, node.module))
    return out


def test_every_package_is_placed_in_the_layer_order() -> None:
    packages = {p.name for p in SRC.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    packages |= {p.stem for p in SRC.glob("*.py") if p.stem != "__init__"}
    assert packages - set(LAYERS) == set(), "add new packages to LAYERS and CONTRACTS.md"


def test_no_import_goes_up_the_layer_order() -> None:
    wrong: list[str] = []
    for path in sorted(SRC.rglob("*.py")):
        rel = path.relative_to(SRC)
        own = rel.parts[0].removesuffix(".py")
        if own == "__init__":
            continue
        for line, module in _imports(path):
            other = _package(module)
            if other is None or other == own or other not in LAYERS:
                continue
            if LAYERS[other] > LAYERS[own] and (rel.as_posix(), module) not in KNOWN:
                wrong.append(f"{rel}:{line}: {own} imports {module}")
    assert wrong == [], "\n".join(wrong)


def test_the_executor_and_the_planner_do_not_ground() -> None:
    for path in sorted((SRC / "execution").rglob("*.py")) + sorted((SRC / "planner").rglob("*.py")):
        for line, module in _imports(path):
            assert not module.startswith("hltl.grounding"), f"{path.name}:{line}: {module}"


def _nested_own_imports(path: Path) -> list[tuple[int, int, str]]:
    """hltl imports that are not at module top (inside a function, a class, an if or a try)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    top = set(map(id, tree.body))
    out: list[tuple[int, int, str]] = []
    for node in ast.walk(tree):
        if id(node) in top or not isinstance(node, ast.Import | ast.ImportFrom):
            continue
        names = [node.module or ""] if isinstance(node, ast.ImportFrom) else []
        names += [a.name for a in node.names] if isinstance(node, ast.Import) else []
        if isinstance(node, ast.ImportFrom) and node.level > 0:
            names = ["hltl"]  # a relative import is one of hltl's own
        own = [n for n in names if n == "hltl" or n.startswith("hltl.")]
        if own:
            assert node.end_lineno is not None
            out.append((node.lineno, node.end_lineno, own[0]))
    return sorted(out)


def _justified(lines: list[str], first: int, last: int) -> bool:
    """A ``# why:`` on the import's own lines or in the comment lines right above it."""
    if any("# why:" in line for line in lines[first - 1 : last]):
        return True
    k = first - 2
    while k >= 0 and lines[k].lstrip().startswith("#"):
        if "# why:" in lines[k]:
            return True
        k -= 1
    return False


def test_own_modules_are_imported_at_module_top_unless_a_why_says_otherwise() -> None:
    # Only optional extras' backends, start-up cost and the CLI's lazy dispatch justify an
    # import of hltl's own modules below module top; each says so with `# why: …`.
    unjustified: list[str] = []
    for path in sorted(SRC.rglob("*.py")):
        lines = path.read_text(encoding="utf-8").splitlines()
        for first, last, module in _nested_own_imports(path):
            if not _justified(lines, first, last):
                unjustified.append(f"{path.relative_to(SRC)}:{first}: {module}")
    assert unjustified == [], "move to module top, or say `# why:`:\n" + "\n".join(unjustified)


def test_the_nested_import_check_sees_function_and_type_checking_imports(tmp_path: Path) -> None:
    module = tmp_path / "m.py"
    module.write_text(
        "from hltl.errors import HltlError\n"
        "if TYPE_CHECKING:\n"
        "    from hltl.world.scene import Scene\n"
        "def f():\n"
        "    import hltl.spec.parser\n"
        "    # why: the extra\n"
        "    from hltl.motion import cost\n"
        "    from numpy import array\n"
        "    from . import sibling\n",
        encoding="utf-8",
    )
    lines = module.read_text(encoding="utf-8").splitlines()
    found = _nested_own_imports(module)
    assert [(first, m) for first, _, m in found] == [
        (3, "hltl.world.scene"),
        (5, "hltl.spec.parser"),
        (7, "hltl.motion"),
        (9, "hltl"),
    ]
    assert [_justified(lines, first, last) for first, last, _ in found] == [
        False,
        False,
        True,
        False,
    ]


# Multi-line module docstrings left while their packages' owners were editing them (session 4);
# their detail belongs in docs/modules.md like the others'. Only ever shrink this set.
LONG_DOCSTRINGS: set[str] = set()


def test_module_docstrings_are_one_line() -> None:
    long = []
    for path in sorted(SRC.rglob("*.py")):
        doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")), clean=True)
        rel = path.relative_to(SRC).as_posix()
        if doc is not None and "\n" in doc.strip() and rel not in LONG_DOCSTRINGS:
            long.append(rel)
    assert long == [], f"one-line module docstrings, the detail in docs/modules.md: {long}"
