"""Session-32 phrasings of issue 12 (engineer 12): blind30's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions
(docs/grounding.md, "Session 32 (engineer 12)"). Each rule with sentences it reads (which fail
with the rule taken out) and near sentences that must stay refused or read otherwise."""

from __future__ import annotations

import pytest

from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips; Person A, Person B
ONE = load_scene(ROOT / "examples/scenes/1-1.yaml")  # bottle (water bottle); Person A

READS = [
    # (a) the speaker's own words as a comma part or sentence of their own (a closed list)
    ("Oh, and before I forget, the apple goes to Bob.", "apple>B", CELL),
    ("Honestly, whenever suits you, give Carol the apple.", "apple>C", CELL),
    ("The apple. Bob's. Off you go.", "apple>B", CELL),
    ("The apple to Bob. Off you go.", "apple>B", CELL),
    ("Give Bob the apple, could you manage that?", "apple>B", CELL),
    # (b) a run-on closed by a break, or by who told the speaker
    ("Give Bob the apple then the cup to Carol then it's tea break", "apple>B ; cup>C", CELL),
    ("Bob wants the apple he told me so and Carol wants the cup", "apple>B & cup>C", CELL),
    # (c) whose opinion, by trade, closing it
    ("Bob gets the apple, and Carol the cup, the farrier reckons.", "apple>B & cup>C", CELL),
    # (d) a courtesy with its language in the third person, or with where it is said
    ("Give Bob the apple. Tenkyu, as my nan says in Tok Pisin.", "apple>B", CELL),
    ("Could Carol have the cup? Dhanyavad, as we say at home in Pune.", "cup>C", CELL),
    # (f) idioms of wanting (a closed list)
    ("Bob has his heart set on the crisps.", "chips>B", CELL),
    ("Carol keeps asking for the apple.", "apple>C", CELL),
    ("Alice has a fancy for the cup.", "cup>A", CELL),
    # (g) asking where it has got to; wanting it back from the robot
    ("Bob is asking where the crisps have got to, can you hand them over?", "chips>B", CELL),
    ("Alice wants her cup back from you.", "cup>A", CELL),
    # (h) what the person needs most
    ("Bob's been on his feet since dawn, and what he needs most is the crisps.", "chips>B", CELL),
    ("The one thing Carol needs at the moment is that apple.", "apple>C", CELL),
    # (i) the cleft in the perfect
    ("The apple is what Carol's been craving.", "apple>C", CELL),
    # (j) a header saying each person wants something
    (
        "They each want something: the apple is what Carol wants, the cup is what Bob asked for.",
        "apple>C & cup>B",
        CELL,
    ),
    # (k) a deadline before something that happens to nothing of the scene
    ("Give Bob the apple before he heads off on his round.", "apple>B", CELL),
    ("Put the cup on the shelf before the kids knock it over.", "cup@shelf", CELL),
    ("Carol wants the apple before the accordion lesson.", "apple>C", CELL),
    # (l) what happened that made the want
    ("Bob would love the apple, the joiners ate all the biscuits.", "apple>B", CELL),
    ("Person A would love the bottle, the lumberjacks drank all the water.", "bottle>A", ONE),
    # (m) possession framed as a handover
    ("The apple's Bob's to take home; the crisps, Carol's.", "apple>B & chips>C", CELL),
    ("The apple's for Bob; the cup is his as well.", "apple>B & cup>B", CELL),
    ("the apple is bob's, give it over please", "apple>B", CELL),
    (
        "The drill is Jess's, the torch goes in the locker, and that's the lot.",
        "drill>B & torch@locker",
        WORKSHOP,
    ),
    # (n) the same person said again in a sentence of its own
    ("Apple first, to Bob. Cup next. Same person, Bob, the farrier.", "apple>B ; cup>B", CELL),
    # (o) the hearer's own tidying
    ("the apple and the cup on the shelf when you clear up", "apple@shelf & cup@shelf", CELL),
    # (q) the object's state, then the request for 'it'
    ("The cup is dirty, put it on the shelf.", "cup@shelf", CELL),
    # (r) who a placement is for, and what they will do with it
    ("Put the apple on the shelf for Carol to eat after her nap.", "apple@shelf", CELL),
    ("Put the magazine on the locker for Mr Lee to read.", "magazine@bedside", WARD),
    # (s) questions that ask another way
    ("Any chance the apple could find its way over to Bob?", "apple>B", CELL),
    ("Don't suppose you could pass Bob the apple?", "apple>B", CELL),
    ("Be good if Carol could get the apple off you.", "apple>C", CELL),
    ("Shall we say the apple goes to Bob and the cup goes to Carol?", "apple>B & cup>C", CELL),
    # (t) 'add' to a surface
    ("Would it be a bother to add the apple to the shelf?", "apple@shelf", CELL),
    # (u) next to an object standing on the surface
    ("Put the white plate on the rack next to the blue one.", "plate_white@rack", KITCHEN),
    # (v) a slip of the word 'person' of a label, even of its first letter
    ("Give Oerson B the chips.", "chips>B", TWO),
    ("Persog A wants the bottle.", "bottle>A", TWO),
    # (x) what the wanted object is for, with what it is done to
    ("Carol needs the cup to stir her tea.", "cup>C", CELL),
    # (y) a reason said as a state of no scene name, closing it
    ("Carol has asked for the cup, the room's too warm.", "cup>C", CELL),
    # (z) how long a want said in the perfect has lasted
    ("Bob has been eyeing the crisps since lunch, so let him have them.", "chips>B", CELL),
    # (aa) where a person is back from
    ("Alice is back from the dive, hand her the cup.", "cup>A", CELL),
    # (bb) who left it where, then the request for 'it'
    ("Somebody left the apple out; put it on the shelf.", "apple@shelf", CELL),
    ("The farrier left the apple out; give it to Bob.", "apple>B", CELL),
    # (cc) who the person is, then what they want
    ("Carol is the farrier and she'd like the apple.", "apple>C", CELL),
    # (dd) where the person is; 'run X down to'; 'can you manage X to'
    ("Could you run the apple down to Bob at the far end?", "apple>B", CELL),
    ("Can you manage the apple to Bob?", "apple>B", CELL),
    # (ee) 'over his way' after the wanted objects
    ("Bob needs the apple and the cup over his way.", "apple>B & cup>B", CELL),
    # (m) possession beside who gets the other thing
    ("The apple is Bob's, and Carol can have the cup.", "apple>B & cup>C", CELL),
    # (w) courtesies of other languages
    ("bob could do with the crisps, zikomo", "chips>B", CELL),
    ("Carol is having the cup, mesi anpil.", "cup>C", CELL),
]


@pytest.mark.parametrize(("text", "want", "scene"), READS)
def test_blind30_kinds_read(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


REFUSED = [
    # (a) not a part of its own; waiting on someone else
    ("Before I forget the apple, give Bob the cup.", CELL),
    ("Whenever Bob is ready, give him the apple.", CELL),
    ("Off you go to Bob with the apple.", CELL),
    # (b) someone's turn after the run-on; a pronoun that cannot be the one person named
    ("Give Bob the apple then it's Carol's turn", CELL),
    ("Mr Lee wants the magazine she told me so and Mrs Khan wants the jug", WARD),
    # (c) a scene word, or a person, who reckons
    ("Bob gets the apple, the cup reckons.", CELL),
    ("Bob gets the apple, Carol reckons.", CELL),
    # (d) said in a place of the scene's kind, not a language
    ("Give Bob the apple, as my nan says in the kitchen.", CELL),
    # (f) an idiom with a pronoun after it that may hand the person something else (causes9)
    ("Carol keeps asking for the apple, give her the cup", CELL),
    ("Bob has his heart set on the crisps, hand him the cup", CELL),
    # (g) asking where a person has got to; back from a person
    ("Bob is asking where Carol has got to.", CELL),
    ("Alice wants her cup back from Bob.", CELL),
    # (h) a person the scene lacks; a person as what is needed
    ("What Dave needs most is the apple.", CELL),
    ("The one thing Bob needs is Carol.", CELL),
    # (i) a person the scene lacks
    ("The apple is what Dave's been craving.", CELL),
    # (j) only one person after the header
    ("They each want something: the apple is what Carol wants.", CELL),
    # (k) a time word; a task of the grammar; a pronoun that cannot be the one person
    ("Give Bob the apple before lunch.", CELL),
    ("Give Bob the apple before he gives Carol the cup.", CELL),
    ("Give Mr Lee the magazine before she heads off.", WARD),
    # (l) what was used up is an object the request does not name
    ("Carol would love the apple, the kids ate all the crisps.", CELL),
    # (m) possession of two without a task beside; 'to give' to someone else; no one before 'his'
    ("The apple is Bob's, the cup is Carol's.", CELL),
    ("The apple is Bob's to give to Carol.", CELL),
    ("The cup is his as well.", CELL),
    ("The apple. Bob's cup.", CELL),
    # (n) another person than the one before
    ("Apple first, to Bob. Cup next. Same person, Carol.", CELL),
    # (o) someone else's tidying
    ("the apple and the cup on the shelf when Bob clears up", CELL),
    # (q) 'it' as a place; a possessor, not a state
    ("The cup is empty, put the apple in it.", CELL),
    ("The cup is Bob's, put it on the shelf.", CELL),
    # (r) a verb of the grammar; a person the scene lacks; a tail naming an object
    ("Put the apple on the shelf for Carol to take.", CELL),
    ("Put the apple on the shelf for Dave to eat.", CELL),
    ("Put the apple on the shelf for Carol to eat after the cup.", CELL),
    # (s) a person the scene lacks; a question after 'shall we say'; a person finding their way
    ("Be good if Dave could get the apple off you.", CELL),
    ("Shall we say who gets the apple?", CELL),
    ("Could Bob find his way over to Carol?", CELL),
    # (t) 'add' to an object or a person
    ("Add the apple to the cup.", CELL),
    ("Add the apple to Bob.", CELL),
    # (u) next to an object not on that surface; not a surface's object at all
    ("Put the white plate on the counter next to the blue one.", KITCHEN),
    ("Put the white plate on the rack next to the lemon.", KITCHEN),
    # (x) a verb of the grammar, or a scene name, after 'to'
    ("Carol needs the cup to give Bob.", CELL),
    ("Carol needs the cup to stir the apple.", CELL),
    # (y) the state of a surface of the scene
    ("Carol has asked for the cup, the shelf is too high.", CELL),
    # (aa) back from a surface of the scene
    ("Alice is back from the shelf, hand her the cup.", CELL),
    # (bb) a person of the scene left it (it may go back to them)
    ("Bob left the apple out; put it on the shelf.", CELL),
    # (cc) a pronoun that cannot be the person
    ("Mr Lee is the porter and she'd like the jug.", WARD),
    # (dd) at a surface of the scene; a person carried
    ("Could you run the apple down to Bob at the table?", CELL),
    ("Could you run the apple down to Bob at the end?", CELL),  # when, or where? (session 26)
    ("Can you manage Bob to Carol?", CELL),
    # (ee) a pronoun that cannot be the one person named
    ("Mr Lee needs the jug over her way.", WARD),
    # (m) a person after 'can have'
    ("The apple is Bob's, and Carol can have him.", CELL),
    # (w) 'I forget' is still the speaker's doubt
    ("I forget who wants the chips, give them to Person B.", TWO),
]


@pytest.mark.parametrize(("text", "scene"), REFUSED)
def test_near_sentences_stay_refused(text: str, scene: object) -> None:
    assert_refused(text, scene)  # type: ignore[arg-type]
