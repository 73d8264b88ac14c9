"""H-LTLf specs: both file layouts, the tree, every validity rule and its message, round trips."""

from __future__ import annotations

import copy
import json
import pickle
from pathlib import Path
from typing import Any

import pytest

from hltl.errors import SpecSyntaxError, SpecValidationError
from hltl.spec.hierarchy import (
    HSpec,
    load_spec,
    spec_from_dict,
    spec_from_formulas,
    spec_to_dict,
    validate_automata,
)
from hltl.spec.parser import parse_formula

FIG1: dict[str, Any] = {
    "root": "p0",
    "formulas": {
        "p0": "F p100 & F p200",
        "p100": "F delivered(bottle, A)",
        "p200": "F delivered(chips, B)",
    },
}
BOTTLE, CHIPS, CUP = "F delivered(bottle, A)", "F delivered(chips, B)", "F placed(cup, shelf)"


def _spec(root: str = "p0", **formulas: str) -> HSpec:
    return spec_from_dict({"root": root, "formulas": formulas})


def test_design_layout() -> None:
    spec = spec_from_dict(FIG1)
    assert spec.root == "p0"
    assert spec.names == ("p0", "p100", "p200")
    assert spec.formula("p100") == parse_formula("F delivered(bottle, A)")
    assert spec.children["p0"] == ("p100", "p200") and spec.children["p100"] == ()
    assert dict(spec.parent) == {"p100": "p0", "p200": "p0"}
    assert spec.leaves == ("p100", "p200") and spec.composites == ("p0",)
    assert spec.levels == (("p0",), ("p100", "p200")) and spec.depth == 2
    assert spec.level_of("p200") == 1 and spec.is_leaf("p200") and not spec.is_leaf("p0")


def test_luo_liu_layout_equals_design_layout() -> None:
    levels = [
        {"p0": "<> p100 && <> p200"},
        {"p100": "<> delivered(bottle, A)", "p200": "<> delivered(chips, B)"},
    ]
    assert spec_from_dict(levels) == spec_from_dict(FIG1)


def test_order_is_canonical_breadth_first() -> None:
    spec = _spec(
        p120="F delivered(bottle, A)",
        p200=CHIPS,
        p0="F p200 & F p100",
        p110="F placed(bottle, shelf)",
        p100="F (p110 & F p120)",
    )
    # root first, then level by level; children in order of first mention in the parent
    assert spec.names == ("p0", "p200", "p100", "p110", "p120")
    assert spec.levels == (("p0",), ("p200", "p100"), ("p110", "p120"))
    assert spec.depth == 3 and spec.leaves == ("p200", "p110", "p120")
    assert spec == _spec(
        p0="F p200 & F p100",
        p100="F (p110 & F p120)",
        p110="F placed(bottle, shelf)",
        p120="F delivered(bottle, A)",
        p200=CHIPS,
    )


def test_round_trip_through_dict() -> None:
    spec = load_spec(Path(__file__).parents[2] / "examples" / "specs" / "office_3.yaml")
    again = spec_from_dict(spec_to_dict(spec))
    assert again == spec
    assert spec_to_dict(again) == spec_to_dict(spec)
    assert spec_to_dict(spec_from_dict(FIG1)) == FIG1


def test_spec_is_hashable_and_compares_by_content() -> None:
    assert hash(spec_from_dict(FIG1)) == hash(spec_from_dict(FIG1))
    assert spec_from_dict(FIG1) != _spec(p0="F (p100 & F p200)", p100=BOTTLE, p200=CHIPS)


def test_spec_pickles_and_copies() -> None:
    spec = load_spec(Path(__file__).parents[2] / "examples" / "specs" / "three_level.yaml")
    for again in (pickle.loads(pickle.dumps(spec)), copy.deepcopy(spec)):
        assert again == spec
        assert dict(again.children) == dict(spec.children) and again.levels == spec.levels


def test_spec_from_formulas_checks_the_tree_only() -> None:
    spec = spec_from_formulas("p0", {"p0": "F (p100 & p200)", "p100": BOTTLE, "p200": CHIPS})
    assert spec.children["p0"] == ("p100", "p200")
    with pytest.raises(SpecValidationError, match="requires p100 and p200"):
        validate_automata(spec)


def test_names_are_tokens_not_substrings() -> None:
    # p10 is not a child of p0 just because "p100" contains it
    with pytest.raises(SpecValidationError, match="p10 is not reachable from the root p0"):
        _spec(p0="F p100", p100=BOTTLE, p10=CHIPS)


@pytest.mark.parametrize(
    ("formulas", "root", "message"),
    [
        # rule 1: composites use their children's names; leaves use predicate atoms
        (
            {"p0": "F p100 & F p300", "p100": BOTTLE},
            "p0",
            "<spec>: p0 refers to 'p300', which is not a formula; formulas are: p0, p100",
        ),
        (
            {"p0": "F p100", "p100": "F bottle"},
            "p0",
            "<spec>: p100 refers to 'bottle', which is not a formula; formulas are: p0, p100 "
            "(leaf formulas use predicate atoms: at(...), delivered(...)",
        ),
        # rule 2: a tree
        (
            {"p0": "F p100 & F p200", "p100": "F p200", "p200": BOTTLE},
            "p0",
            "<spec>: p200 is a child of both p0 and p100; every formula except the root must "
            "appear in exactly one parent (rule 2",
        ),
        (
            {"p0": "F picked(cup)", "p100": "F p200", "p200": "F p100"},
            "p0",
            "<spec>: cycle: p200 -> p100 -> p200; the hierarchy must be a tree",
        ),
        ({"p0": "F p0"}, "p0", "<spec>: p0 refers to itself"),
        (
            {"p0": "F p100", "p100": "F p0 & F picked(cup)"},
            "p0",
            "<spec>: the root p0 has no parent, but p100 refers to it",
        ),
        (
            {"p0": "F p100", "p100": BOTTLE, "p200": CHIPS},
            "p0",
            "<spec>: p200 is not reachable from the root p0: no formula refers to it",
        ),
        (
            {"p0": "F p100", "p100": BOTTLE, "p300": CHIPS, "p200": "F p300"},
            "p0",
            "<spec>: p300 is not reachable from the root p0: its ancestor p200 is not referred "
            "to by any formula",
        ),
        (
            {"p0": "F p100", "p100": BOTTLE},
            "p9",
            "<spec>: root 'p9' is not a formula; formulas are: p0, p100",
        ),
        ({}, "p0", "<spec>: the specification has no formulas"),
        ({"F": BOTTLE}, "F", "<spec>: formula name 'F' is an operator or predicate name"),
        ({"picked": BOTTLE}, "picked", "<spec>: formula name 'picked' is an operator or"),
        ({"p-1": BOTTLE}, "p-1", "<spec>: formula name 'p-1' is not an identifier"),
        # rule 3: no two children required in the same step
        (
            {"p0": "F (p100 & p200)", "p100": BOTTLE, "p200": CHIPS},
            "p0",
            "<spec>: p0: 'F (p100 & p200)' requires p100 and p200 to complete in the same step, "
            "which rule 3 forbids (children complete independently); write 'F p100 & F p200' if "
            "all must complete, or 'F (p100 & F p200)' for this order",
        ),
        (
            {"p0": "F (p100 & p200 & p300)", "p100": BOTTLE, "p200": CHIPS, "p300": CUP},
            "p0",
            "<spec>: p0: 'F (p100 & p200 & p300)' requires p100, p200 and p300 to complete in "
            "the same step",
        ),
        (
            # only the pair that must coincide is named, not p300
            {"p0": "F (p100 & p200) & F p300", "p100": BOTTLE, "p200": CHIPS, "p300": CUP},
            "p0",
            "<spec>: p0: 'F (p100 & p200) & F p300' requires p100 and p200 to complete in the "
            "same step",
        ),
        (
            {"p0": "G (p100 <-> p200) & F p100", "p100": BOTTLE, "p200": CHIPS},
            "p0",
            "<spec>: p0: 'G (p100 <-> p200) & F p100' requires p100 and p200 to complete",
        ),
        # satisfiability
        (
            {"p0": "F p100 & G !p100", "p100": BOTTLE},
            "p0",
            "<spec>: p0: 'F p100 & G !p100' is unsatisfiable",
        ),
        (
            {"p0": "F p100", "p100": "F picked(cup) & G !picked(cup)"},
            "p0",
            "<spec>: p100: 'F picked(cup) & G !picked(cup)' is unsatisfiable",
        ),
        (
            {"p0": "F (p100 & X F p100)", "p100": BOTTLE},
            "p0",
            "<spec>: p0: 'F (p100 & X F p100)' cannot be satisfied when each child completes "
            "once (children are one-shot events",
        ),
    ],
)
def test_validity_rules(formulas: dict[str, str], root: str, message: str) -> None:
    with pytest.raises(SpecValidationError) as info:
        spec_from_dict({"root": root, "formulas": formulas})
    assert str(info.value).startswith(message)


@pytest.mark.parametrize(
    "p0",
    [
        "F p100 & F p200",  # together or apart
        "F (p100 & F p200)",  # non-strict order
        "F p100 | F p200",
        "F (p100 & p200) | F p100",  # the disjunct needing both at once is not needed
        "!p200 U p100 & F p200",
        "F (p100 & X F p200)",  # strict order
    ],
)
def test_composites_that_respect_rule_3(p0: str) -> None:
    assert set(_spec(p0=p0, p100=BOTTLE, p200=CHIPS).children["p0"]) == {"p100", "p200"}


def test_atoms_in_a_composite_are_allowed() -> None:
    spec = _spec(p0="F p100 & G !at(cup, shelf)", p100=BOTTLE)
    assert spec.children["p0"] == ("p100",)


def test_luo_liu_layout_errors() -> None:
    with pytest.raises(SpecValidationError, match="the first level holds the root alone; it has 2"):
        spec_from_dict([{"p0": "<> p100", "p1": "<> p100"}, {"p100": BOTTLE}])
    with pytest.raises(
        SpecValidationError, match=r"formula p100 is defined twice \(levels 2 and 3\)"
    ):
        spec_from_dict([{"p0": "<> p100"}, {"p100": BOTTLE}, {"p100": CHIPS}])
    with pytest.raises(
        SpecValidationError, match="p200 is listed in level 3 but its parent p0 is in level 1"
    ):
        spec_from_dict([{"p0": "<> p100 && <> p200"}, {"p100": BOTTLE}, {"p200": CHIPS}])
    with pytest.raises(SpecValidationError, match="the list of levels is empty"):
        spec_from_dict([])
    with pytest.raises(SpecValidationError, match="level 2 must map names to formulas, got str"):
        spec_from_dict([{"p0": "<> p100"}, "p100"])


def test_layout_errors_name_the_source() -> None:
    cases: list[tuple[Any, str]] = [
        ({"root": "p0", "formulas": FIG1["formulas"], "extra": 1}, "unknown key 'extra'"),
        ({"root": "p0"}, "missing 'formulas'"),
        ({"formulas": FIG1["formulas"]}, "missing 'root'"),
        ({"root": 0, "formulas": FIG1["formulas"]}, "'root' must be a formula name, got 0"),
        ({"root": "p0", "formulas": ["F p100"]}, "'formulas' must map names to formulas, got list"),
        ({"root": "p0", "formulas": {"p0": 5}}, "formula p0 must be a string, got int 5"),
        ({"root": "p0", "formulas": {100: BOTTLE}}, "formulas: formula name 100 must be a string"),
        ("F p100", "a spec is a mapping {root: p0, formulas: {p0: ..., p100: ...}} or a list"),
    ]
    for data, message in cases:
        with pytest.raises(SpecValidationError) as info:
            spec_from_dict(data, source="task.yaml")
        assert str(info.value).startswith("task.yaml: "), str(info.value)
        assert message in str(info.value)


def test_syntax_error_names_source_and_formula() -> None:
    data = {"root": "p0", "formulas": {"p0": "F (p100 & )", "p100": BOTTLE}}
    with pytest.raises(SpecSyntaxError) as info:
        spec_from_dict(data, source="task.yaml")
    assert str(info.value).startswith(
        "task.yaml: formula p0: unexpected ')' at line 1, column 11 in \"F (p100 & )\""
    )
    assert (info.value.line, info.value.column) == (1, 11)


def test_check_automata_can_be_skipped() -> None:
    data = {"root": "p0", "formulas": {"p0": "F (p100 & p200)", "p100": BOTTLE, "p200": CHIPS}}
    assert spec_from_dict(data, check_automata=False).depth == 2


def test_load_yaml_and_json(tmp_path: Path) -> None:
    (tmp_path / "fig1.json").write_text(json.dumps(FIG1))
    (tmp_path / "fig1.yaml").write_text(
        "- p0: '<> p100 && <> p200'\n"
        "- p100: '<> delivered(bottle, A)'\n"
        "  p200: '<> delivered(chips, B)'\n"
    )
    assert load_spec(tmp_path / "fig1.json") == load_spec(str(tmp_path / "fig1.yaml"))


def test_load_errors_name_the_file(tmp_path: Path) -> None:
    missing = tmp_path / "missing.yaml"
    with pytest.raises(SpecValidationError, match=f"{missing}: cannot read spec: No such file"):
        load_spec(missing)
    bad = tmp_path / "bad.yaml"
    bad.write_text("root: [p0\n")
    with pytest.raises(SpecValidationError, match=f"{bad}: not valid YAML"):
        load_spec(bad)
    bad_json = tmp_path / "bad.json"
    bad_json.write_text("{")
    with pytest.raises(SpecValidationError, match=f"{bad_json}: not valid JSON"):
        load_spec(bad_json)
    invalid = tmp_path / "invalid.yaml"
    invalid.write_text("root: p0\nformulas: {p0: 'F p100 & F p300', p100: 'F picked(cup)'}\n")
    with pytest.raises(SpecValidationError, match=f"{invalid}: p0 refers to 'p300'"):
        load_spec(invalid)


def test_formula_lookup_errors() -> None:
    spec = spec_from_dict(FIG1)
    with pytest.raises(KeyError, match="no formula 'p300'; formulas are: p0, p100, p200"):
        spec.formula("p300")
    with pytest.raises(KeyError, match="no formula 'p300'"):
        spec.level_of("p300")


EXAMPLES = sorted((Path(__file__).parents[2] / "examples" / "specs").glob("*.yaml"))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_examples_are_valid(path: Path) -> None:
    spec = load_spec(path)
    assert spec.leaves and all(spec.parent.get(n) or n == spec.root for n in spec.names)


def test_example_shapes() -> None:
    root = Path(__file__).parents[2] / "examples" / "specs"
    assert {p.name for p in EXAMPLES} >= {
        "fig1.yaml",
        "ordered.yaml",
        "unordered.yaml",
        "either.yaml",
        "three_level.yaml",
        "office_1.yaml",
        "office_2.yaml",
        "office_3.yaml",
    }
    assert load_spec(root / "fig1.yaml") == spec_from_dict(FIG1)
    assert load_spec(root / "three_level.yaml").depth == 3
    assert load_spec(root / "office_3.yaml").depth == 3
    assert len(load_spec(root / "unordered.yaml").leaves) == 3
