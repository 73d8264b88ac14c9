"""Offline grounder details: naming, encoding, lexicon rules, determinism."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.errors import GroundingError
from hltl.grounding import Grounder, make_grounder
from hltl.grounding.lexicon import Lexicon, lex, tokenize
from hltl.grounding.offline import OfflineGrounder, parse_instruction
from hltl.grounding.tree import Group, Node, Task, decode, encode, normalise
from hltl.grounding.tree import tasks as tasks_of
from hltl.spec.hierarchy import spec_from_formulas, spec_to_dict
from hltl.world.scene import Scene, load_scene, scene_from_dict


def test_offline_grounder_is_a_grounder() -> None:
    assert isinstance(OfflineGrounder(), Grounder)
    assert isinstance(make_grounder("offline"), OfflineGrounder)


def test_design_example(two_arms: Scene) -> None:
    g = OfflineGrounder().ground("Give Person A the bottle and Person B the chips", two_arms)
    assert spec_to_dict(g.spec) == {
        "root": "p0",
        "formulas": {
            "p0": "F p100 & F p200",
            "p100": "F delivered(bottle, A)",
            "p200": "F delivered(chips, B)",
        },
    }


def test_leaves_are_numbered_in_text_order_and_groups_get_small_names(cell: Scene) -> None:
    text = "give A the cup and the bottle, then give B the chips or the apple"
    f = spec_to_dict(OfflineGrounder().ground(text, cell).spec)["formulas"]
    assert f == {
        "p0": "F (p1 & F p2)",
        "p1": "F p100 & F p200",
        "p2": "F p300 | F p400",
        "p100": "F delivered(cup, A)",
        "p200": "F delivered(bottle, A)",
        "p300": "F delivered(chips, B)",
        "p400": "F delivered(apple, B)",
    }


def test_same_instruction_same_spec(cell: Scene) -> None:
    text = "first give Carol the apple, then put the cup and the bottle on the shelf"
    a, b = (OfflineGrounder().ground(text, cell).spec for _ in range(2))
    assert spec_to_dict(a) == spec_to_dict(b)


def test_capital_letter_id_versus_article(two_arms: Scene) -> None:
    # "a" is an article; "A" names Person A (one-letter ids match with their case only)
    assert parse_instruction("give a bottle to A", two_arms) == Task("deliver", "bottle", "A")
    with pytest.raises(GroundingError, match="no recipient"):
        parse_instruction("give a bottle", two_arms)


def test_keyword_names_need_their_spelling() -> None:
    scene = scene_from_dict(
        {
            "robots": [{"id": "r1", "base": [0, 0, 0], "reach": 1}],
            "objects": [{"id": "cup", "position": [0.1, 0, 0]}],
            "humans": [{"id": "W", "name": "Will", "position": [0.5, 0, 0]}],
        }
    )
    assert parse_instruction("give Will the cup", scene) == Task("deliver", "cup", "W")
    # lower-case "will" is the auxiliary verb here
    assert parse_instruction("you will give the cup to W", scene) == Task("deliver", "cup", "W")


def test_tokenize_contractions_and_quotes() -> None:
    words = [t.low for t in tokenize("Don’t give Bob’s cup, please!")]
    assert words == ["do", "n't", "give", "bob", "'s", "cup", ",", "please", "!"]


def test_lexicon_prefers_ids_and_aliases_over_categories() -> None:
    scene = scene_from_dict(
        {
            "robots": [{"id": "r1", "base": [0, 0, 0], "reach": 1}],
            "objects": [
                {"id": "bottle", "category": "bottle", "position": [0.1, 0, 0]},
                {"id": "bottle2", "category": "bottle", "position": [0.2, 0, 0]},
            ],
            "humans": [{"id": "A", "name": "Person A", "position": [0.5, 0, 0]}],
        }
    )
    items = lex("the bottle and the bottles", Lexicon(scene))
    ents = [i for i in items if i.kind == "ent"]
    assert [r.id for r in ents[0].refs] == ["bottle"]
    assert sorted(r.id for r in ents[1].refs) == ["bottle", "bottle2"]


def test_unknown_words_next_to_a_name_are_reported_together(cell: Scene) -> None:
    with pytest.raises(GroundingError, match="no object called 'big red mug'"):
        parse_instruction("give A the big red mug", cell)


def test_error_lists_aliases_kinds(cell: Scene) -> None:
    with pytest.raises(GroundingError, match="'shelf' is a surface, not an object"):
        parse_instruction("give A the shelf", cell)
    with pytest.raises(GroundingError, match="'cup' is an object, not a person"):
        parse_instruction("give the apple to the cup", cell)


# -- encoding -----------------------------------------------------------------------------------

OBJECTS, PEOPLE = ("cup", "bottle", "chips", "apple"), ("A", "B", "C")
tasks = st.builds(Task, st.just("deliver"), st.sampled_from(OBJECTS), st.sampled_from(PEOPLE))
trees = st.recursive(
    tasks,
    lambda kids: st.builds(
        Group,
        st.sampled_from(["and", "or", "seq"]),
        st.lists(kids, min_size=2, max_size=3).map(tuple),
    ),
    max_leaves=6,
)


@settings(max_examples=150, deadline=None)
@given(trees)
def test_encode_then_decode_is_the_normalised_tree(tree: Node) -> None:
    formulas = encode(tree)
    spec = spec_from_formulas("p0", formulas)
    norm = normalise(tree)
    decoded = decode(spec)
    if isinstance(norm, Task):  # a lone task is wrapped by the root
        assert decoded == Group("and", (norm,))
    else:
        assert decoded == norm
    leaves = [n for n in spec.names if spec.is_leaf(n)]
    assert sorted(leaves, key=lambda n: int(n[1:])) == [
        f"p{100 * k}" for k in range(1, len(leaves) + 1)
    ]


def test_normalise_flattens_same_operators() -> None:
    a, b, c = (Task("deliver", o, "A") for o in ("cup", "bottle", "chips"))
    assert normalise(Group("seq", (Group("seq", (a, b)), c))) == Group("seq", (a, b, c))
    assert normalise(Group("and", (a, Group("or", (b, c))))) == Group(
        "and", (a, Group("or", (b, c)))
    )
    assert normalise(Group("or", (a,))) == a


VOCAB = [
    "give",
    "hand",
    "bring",
    "put",
    "place",
    "pick",
    "up",
    "it",
    "the",
    "a",
    "A",
    "B",
    "C",
    "Alice",
    "Bob",
    "Carol",
    "Person",
    "cup",
    "bottle",
    "chips",
    "apple",
    "mug",
    "mugs",
    "shelf",
    "table",
    "and",
    "or",
    ",",
    ".",
    ";",
    "either",
    "both",
    "then",
    "first",
    "after",
    "before",
    "once",
    "when",
    "to",
    "for",
    "on",
    "onto",
    "instead",
    "cancel",
    "also",
    "as",
    "well",
    "as",
    "has",
    "wants",
    "is",
    "been",
    "her",
    "not",
    "r1",
    "red",
    "meanwhile",
]


SCENE = load_scene(Path(__file__).parents[2] / "examples" / "scenes" / "grounding_cell.yaml")


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(VOCAB), min_size=0, max_size=12))
def test_any_text_parses_or_says_why(words: list[str]) -> None:
    scene = SCENE
    try:
        node = parse_instruction(" ".join(words), scene)
    except GroundingError as exc:
        assert str(exc)  # a reason, never an empty message
    else:
        assert all(t.obj in scene.object_ids for t in tasks_of(node))
