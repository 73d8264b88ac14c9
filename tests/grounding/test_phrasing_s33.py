"""Session-33 phrasings of issue 12 (engineer 12): blind31's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions
(docs/grounding.md, "Session 33 (engineer 12)"). Each rule with sentences it reads (which fail
with the rule taken out) and near sentences that must stay refused or read otherwise."""

from __future__ import annotations

import pytest

from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    NURSERY,
    OFFICE,
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
    ("Nothing fancy today, just the apple for Bob, thanks.", "apple>B", CELL),
    ("Oh, go on then, the cup to Carol.", "cup>C", CELL),
    ("The apple? Bob. The cup? Carol. Simple as that.", "apple>B & cup>C", CELL),
    # (a') 'all yours' said to the person just addressed
    ("The cup, Carol, there you go, all yours.", "cup>C", CELL),
    ("The cup, Carol, all yours.", "cup>C", CELL),
    ("Cheers in advance, the apple to Bob.", "apple>B", CELL),
    (
        "The crisps for Alice. The cup too. And, oh yes, the apple.",
        "chips>A & cup>A & apple>A",
        CELL,
    ),
    ("Apple for Bob, cup for Carol, no rush on either of them.", "apple>B & cup>C", CELL),
    # (b) thanks of other languages (the session-24 list)
    ("Kadrinchey la, and sorry to bother you, but Bob is asking for the apple.", "apple>B", CELL),
    ("Place the water bottle, no, hand it to Person A, ua tsaug.", "bottle>A", ONE),
    ("Chips to Person B, no, to Person A, natotela.", "chips>A", TWO),
    # (c) idioms of wanting (a closed list), before objects only
    ("Alice could murder the crisps.", "chips>A", CELL),
    ("Bob's asking after the apple.", "apple>B", CELL),
    ("Carol is asking after the cup, she's the farrier.", "cup>C", CELL),
    # (d) what would help a person; how much they need it
    ("The cup would help Carol a lot.", "cup>C", CELL),
    ("the apple would help bob no end", "apple>B", CELL),
    ("Bob needs the apple more than anyone else.", "apple>B", CELL),
    # (e) whose word it is, by trade
    ("Alice wants the cup, according to the farrier.", "cup>A", CELL),
    ("The crisps are wanted by Carol, apparently, according to the roadie.", "chips>C", CELL),
    # (f) the time of the event the thing is for
    ("Carol needs the cup for her violin lesson this afternoon.", "cup>C", CELL),
    ("Mr Lee needs the magazine for his physio session later.", "magazine>B", WARD),
    # (g) a closing remark of what made the request
    ("Give Bob the apple, the telly in the lounge has packed up.", "apple>B", CELL),
    (
        "Mrs Khan is to have the grey blanket, the radiator by her bed's packed in.",
        "blanket_grey>C",
        WARD,
    ),
    ("Give Bob the apple, the little one's got jam all over the place.", "apple>B", CELL),
    (
        "Grandad wants the bib, the little one's got yoghurt absolutely everywhere.",
        "bib>B",
        NURSERY,
    ),
    ("Give Mr Lee the jug, the cardiologist's told him to drink more.", "jug>B", WARD),
    ("Put the apple on the shelf, the dentist is coming to use the counter.", "apple@shelf", CELL),
    (
        "All the pens into the box, the optometrist is coming to use the desk.",
        "pen_black@box & pen_blue@box & pen_red@box",
        OFFICE,
    ),
    # (h) in the perfect, what was done to earn it
    ("Bob has earned the crisps after mending the fence.", "chips>B", CELL),
    ("Person A has earned the water bottle after hauling the nets in.", "bottle>A", ONE),
    # (i) each person, then 'that's' what they get, in order
    ("Alice first, that's the cup; next up Bob, that's the apple.", "cup>A ; apple>B", CELL),
    (
        "Carol first, that's the crisps. Then Alice, that's the red mug.",
        "chips>C ; mug_red>A",
        CELL,
    ),
    # (j) the thing pointed out, then who wants it
    ("There's an apple over there, yeah? Bob wants it.", "apple>B", CELL),
    ("There's a teddy, Lily would like it.", "teddy>A", NURSERY),
    # (k) whose it is, then the handover of 'it' to them
    ("That's Bob's apple, take it over to him.", "apple>B", CELL),
    (
        "That's Kofi's drill, take it over to him, and the screws with it.",
        "drill>A & screws>A",
        WORKSHOP,
    ),
    # (l) the person's own things, and where they want them
    ("Alice wants her cup on the shelf.", "cup@shelf", CELL),
    ("Mrs Khan wants her magazine on the trolley.", "magazine@trolley", WARD),
    # (m) a slip in the second word of an object's name of two words
    ("Baby wpies to Ava, there's been a spill.", "wipes>C", NURSERY),
    ("The baby wipse go to Grandad.", "wipes>B", NURSERY),
    # (n) questions said another way
    ("Do you think Carol could have the apple?", "apple>C", CELL),
    ("Is it okay if the apple goes on the shelf?", "apple@shelf", CELL),
    ("Is it alright if the jug goes up on the trolley, out of harm's way?", "jug@trolley", WARD),
    # (o) a spot on the surface by a thing the scene does not have
    ("Put the apple on the counter by the kettle.", "apple@table", CELL),
    (
        "Would you mind setting the red mug down on the counter by the kettle?",
        "mug_red@table",
        CELL,
    ),
    ("Set the cup down on the shelf near the window.", "cup@shelf", CELL),
    # (p) the same kinds in blind24 and blind29: a cleft putting the person first
    ("It's Carol who ordered the apple, so hand it over to them, would you.", "apple>C", CELL),
    # (q) 'been on about' (wants), 'again' of it; 'hand it over' run on after a want
    ("Bob's been on about the apple.", "apple>B", CELL),
    ("alice's been on about the cup again hand it over", "cup>A", CELL),
    # (r) the request reported from someone of a trade
    ("The farrier says Carol should have the apple.", "apple>C", CELL),
    # (s) who lent the things, by trade
    (
        "Sam can have the pens, the caretaker's lent us them.",
        "pen_black>B & pen_blue>B & pen_red>B",
        OFFICE,
    ),
    # (t) the speaker's hands, run on at the end
    ("put the cup on the shelf for me my hands are full of flour", "cup@shelf", CELL),
    ("can you put the cup on the shelf for me my hands are all wet", "cup@shelf", CELL),
    # (u) 'start with' what is first
    (
        "start off with the cup for alice and after that bob needs the apple",
        "cup>A ; apple>B",
        CELL,
    ),
    # (v) what it is for, of that person
    ("Bob needs the crisps to keep him going, and Carol the apple.", "chips>B & apple>C", CELL),
    ("Mr Lee needs the jug to tide him over.", "jug>B", WARD),
    # (w) whose the things are, then the handover to that same person
    (
        "The apple is for Bob, and the cup, well, that's Carol's, so give it to Carol.",
        "apple>B & cup>C",
        CELL,
    ),
    (
        "The apple is for Bob, and the cup, that's Carol's, so hand it over to Carol.",
        "apple>B & cup>C",
        CELL,
    ),
    # (a) a header of the speaker's: a quick one before a bell
    ("Quick one before the bell: the apple to Bob.", "apple>B", CELL),
    # (b) a courtesy or address before 'please' without a comma
    ("Chale please the apple to Bob.", "apple>B", CELL),
]


@pytest.mark.parametrize(("text", "want", "scene"), READS)
def test_blind31_kinds_read(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


REFUSED = [
    # (a) a part of the list with nothing named after it, or with no one named
    ("Go on then.", CELL),
    # (a') 'all yours' with no person addressed just before it: whose?
    ("The cup, all yours.", CELL),
    ("The cup to Bob, the apple, all yours.", CELL),
    ("Bob gets the cup. The apple, all yours.", CELL),
    ("Simple as that.", CELL),
    ("No rush on the apple, the cup to Carol.", CELL),
    # (c) an idiom before a person; a pronoun after it that may hand her something else
    ("Bob could murder Carol.", CELL),
    ("Bob is asking after Carol.", CELL),
    ("Alice could murder the crisps, give her the cup.", CELL),
    # (d) nobody helped, a person who helps, two people; more than another person
    ("The cup would help.", CELL),
    ("Bob would help Carol.", CELL),
    ("The cup would help Bob and Carol.", CELL),
    ("Bob needs the apple more than Carol.", CELL),
    # (e) a person of the scene, not a trade
    ("Alice wants the cup, according to Bob.", CELL),
    # (f) a time said of the task itself
    ("Carol needs the cup this afternoon.", CELL),
    # (g) a broken thing of the scene; a person of the scene told him; a pronoun that cannot be
    # the one person named; the surface the request uses
    ("Give Bob the apple, the cup's packed in.", CELL),
    ("Give Bob the apple, Carol's told him to cut down.", CELL),
    ("Give Mrs Khan the jug, the doctor's told him to cut down.", WARD),
    ("Put the apple on the shelf, the dentist is coming to use the shelf.", CELL),
    # (h) no '-ing' after 'after': a time
    ("Bob has earned the crisps after lunch.", CELL),
    # (i) no order said; the second without its order word
    ("Alice, that's the cup.", CELL),
    ("Alice first, that's the cup; Bob, that's the apple.", CELL),
    # (j) no 'it'; a person pointed out
    ("There's an apple over there, yeah? Bob wants the cup.", CELL),
    ("There's Carol over there, yeah? Bob wants it.", CELL),
    # (k) to another person; a pronoun that cannot be the owner
    ("That's Bob's apple, take it over to Carol.", CELL),
    ("That's Mrs Khan's jug, take it over to him.", WARD),
    # (l) a pronoun that cannot be the person
    ("Mrs Khan wants his jug on the trolley.", WARD),
    # (m) a slip of another object's name after the first word
    ("Baby beakr to Ava.", NURSERY),
    # (n) a want asked about; a person going somewhere
    ("Do you think Carol wants the apple?", CELL),
    ("Is it okay if Bob goes on the shelf?", CELL),
    # (o) by a person; by a time
    ("Put the apple on the counter by Bob.", CELL),
    ("Put the apple on the shelf by the weekend.", CELL),
    # (o) a participle after a want list, not a verb of placing opening the clause (session 10)
    ("Ruth wants the thermometer and the tablets put on the cart by the bed", WARD),
    # (p) a verb of no want; a person after it
    ("It's Carol who gave Bob the apple.", CELL),
    ("It's Carol who ordered Bob.", CELL),
    # (q) a person after it; a pronoun after it; 'again' of a plain want
    ("Bob's been on about Carol.", CELL),
    ("Bob's been on about the apple, give him the cup.", CELL),
    ("Bob wants the apple again hand it over", CELL),
    # (r) a pronoun or the speaker in what is reported
    ("The farrier says she should have the apple.", CELL),
    ("The farrier says give me the apple.", CELL),
    # (s) a person of the scene lent it
    ("Sam can have the pens, Priya's lent us them.", OFFICE),
    # (t) hands said with a scene name
    ("Put the cup on the shelf, my hands are all apple.", CELL),
    # (u) no one named with what is first
    ("start off with the cup and after that bob needs the apple", CELL),
    # (v) a pronoun that cannot be the one person named
    ("Mrs Khan needs the jug to keep him going.", WARD),
    # (w) the handover to another person than the owner
    ("The apple is for Bob, and the cup, that's Carol's, so give it to Alice.", CELL),
    # (a) before a person
    ("Quick one before Carol: the apple to Bob.", CELL),
]


@pytest.mark.parametrize(("text", "scene"), REFUSED)
def test_near_sentences_stay_refused(text: str, scene: object) -> None:
    assert_refused(text, scene)  # type: ignore[arg-type]
