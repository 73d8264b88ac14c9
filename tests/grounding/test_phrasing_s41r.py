"""Session-41 phrasings of issue 12 (engineer 12r): blind39's negation, choice and distribution
idioms, counts and corrections, each as a family; docs/grounding.md, "Session 41 (engineer 12r)".
Each rule with sentences of its kind in other words and scenes, and near forms that must stay
refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import (
    _rewrites41r,
    _rewrites42r,
    _rewrites43r,
    _rewrites44r,
    _rewrites44s,
    _rewrites50l,
    _rewrites52r,
    _rewrites53s,
    offline,
)
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_reads,
)

CASES = PhrasingCases()

# -- negation and exclusion ------------------------------------------------------------------------

test_neg = CASES.test(
    # _everything_but41r
    (
        "Every single item except the knife goes to Marco.",
        "plate_white>A & lemon>A & salt>A & plate_blue>A & tongs>A",
        KITCHEN,
    ),
    (
        "Give Jess each and every thing bar the drill.",
        "spanner_small>B & hammer>B & screws>B & torch>B & spanner_large>B",
        WORKSHOP,
    ),
    ("Everything not counting the pens to Priya.", "notebook>A & stapler>A", OFFICE),
    ("Everything excepting the boxes goes to Tom.", "scanner>B & tape>B & gloves>B", DEPOT),
    ("Every last thing bar the mugs goes to Alice.", "cup>A & bottle>A & chips>A & apple>A", CELL),
    ("Every last thing bar the kettle goes to Alice.", None, CELL),
    ("Every single item not counting Marco goes to Lena.", None, KITCHEN),
    # _not_its41r
    ("Not the spoon, mind, it's the banana that Emma's after.", "banana>C", LAB),
    ("Never mind about the stapler; it's the notebook Sam wants.", "notebook>B", OFFICE),
    ("Forget the magazine, it's the jug Mrs Khan needs.", "jug>C", WARD),
    ("Not the spoon, it's the spoon that Emma's after.", None, LAB),
    ("Not the spoon, it's the banana that the tray's after.", None, LAB),
    ("Never mind about the stapler; it's the notebook.", None, OFFICE),
    # _forget_after41r
    ("Pass Zoe the ruler, forget about the globe for her.", "ruler>C", CLASSROOM),
    ("Give Kofi the drill, never mind the hammer.", "drill>A", WORKSHOP),
    ("Hand Tom the tape, skip the gloves.", "tape>B", DEPOT),
    ("Give Kofi the drill, forget about the drill.", None, WORKSHOP),
    ("Give Kofi the drill, forget about it.", None, WORKSHOP),
    ("Forget about the hammer.", None, WORKSHOP),
    # _not_for_after41r
    ("Noah's to have the green book; the red one's not for him.", "book_green>B", CLASSROOM),
    ("Give Lena the white plate; the blue one isn't for her.", "plate_white>B", KITCHEN),
    ("Give Lena the white plate; the white one isn't for her.", None, KITCHEN),
    # _no_wait41r
    ("Nothing to wait for, the tongs can go to Marco straight off.", "tongs>A", KITCHEN),
    ("No point waiting, pass Omar the bowl.", "bowl>B", LAB),
    ("No point waiting, the beaker goes to Lily straight off.", "beaker>A", NURSERY),
    ("Nothing to wait for.", None, KITCHEN),
    # _left_that_isnt41r
    (
        "Whatever's left that isn't the stapler goes to Sam.",
        "pen_black>B & notebook>B & pen_blue>B & pen_red>B",
        OFFICE,
    ),
    (
        "Anything remaining that's not the knife goes to Lena.",
        "plate_white>B & lemon>B & salt>B & plate_blue>B & tongs>B",
        KITCHEN,
    ),
    ("Whatever's left that isn't the kettle goes to Sam.", None, OFFICE),
    # _instead_of_unwanted41r
    ("Jess doesn't need the hammer, hand her the torch instead.", "torch>B", WORKSHOP),
    ("Keep the knife away from Mr Novak and give him the lemon instead.", "lemon>C", KITCHEN),
    ("Sam doesn't want the stapler, give him the notebook instead.", "notebook>B", OFFICE),
    ("Jess doesn't need the hammer, hand her the hammer instead.", None, WORKSHOP),
    ("Jess doesn't need the hammer, hand it to her instead.", None, WORKSHOP),
    ("Keep the knife away from Mr Novak.", None, KITCHEN),
)

# -- choice and distribution idioms ----------------------------------------------------------------

test_choice = CASES.test(
    # _left_to_you41r
    ("Give the bib to Grandad or Ava, take your pick.", "bib>B | bib>C", NURSERY),
    ("A cup for Emma, green or white, take your pick.", "cup_green>C | cup_white>C", LAB),
    (
        "A block for Lily, red or green, grab whichever is handy.",
        "block_red>A | block_green>A",
        NURSERY,
    ),
    # _whichever_free41r
    ("Marco or Lena, whichever's free, can take the salt.", "salt>A | salt>B", KITCHEN),
    ("Priya or Sam, whoever is around, should get the stapler.", "stapler>A | stapler>B", OFFICE),
    ("Marco or the counter, whichever's free, can take the salt.", None, KITCHEN),
    # _a_kind_said41r
    (
        "Put a box on the pallet, the small or the large, your call.",
        "box_small@pallet | box_large@pallet",
        DEPOT,
    ),
    ("Hand Mia a box, the medium or the large.", "box_medium>A | box_large>A", DEPOT),
    ("Put a plate on the rack, the white or the green, your call.", None, KITCHEN),
    # _fussy_between41r
    (
        "Kofi isn't fussy between the drill and the torch, bring whichever's closest.",
        "drill>A | torch>A",
        WORKSHOP,
    ),
    ("Emma's not picky about the bowl or the spoon, give her either.", "bowl>C | spoon>C", LAB),
    (
        "Kofi isn't fussy between the drill and the drill, bring whichever's closest.",
        None,
        WORKSHOP,
    ),
    # _so_long_as41r
    (
        "Zoe can have whatever book she likes so long as it isn't the red one.",
        "book_green>C",
        CLASSROOM,
    ),
    (
        "Kofi can take any spanner he wants as long as it's not the small one.",
        "spanner_large>A",
        WORKSHOP,
    ),
    ("Zoe can have whatever book she likes so long as it isn't the blue one.", None, CLASSROOM),
    # _one_of_them_gets41r
    ("Hand one of them the tape, Mia or Tom.", "tape>A | tape>B", DEPOT),
    ("Give one of them the tongs, Marco or Lena, I'll let you pick.", "tongs>A | tongs>B", KITCHEN),
    ("Hand one of them the tape, Mia or Mia.", None, DEPOT),
    # _shared_out41r
    (
        "A book apiece for the pupils: the red one to Noah, the green one to Zoe.",
        "book_red>B & book_green>C",
        CLASSROOM,
    ),
    (
        "Share them out, one each: the drill for Kofi, the torch for Jess.",
        "drill>A & torch>B",
        WORKSHOP,
    ),
    (
        "Split the four things down the middle: pen and notebook for Priya, and stapler plus "
        "red pen for Sam.",
        None,
        OFFICE,
    ),
    (
        "Each patient gets a blanket: the grey one to Mr Lee and the blue one to Mrs Khan.",
        "blanket_grey>B & blanket_blue>C",
        WARD,
    ),
    (
        "Each student gets a book: the green one to Zoe and the red one to Mrs Ortiz.",
        None,
        CLASSROOM,
    ),
    ("A book apiece for the pupils: the red one and the green one to Noah.", None, CLASSROOM),
    ("Split the two things down the middle: the drill and the torch for Kofi.", None, WORKSHOP),
    (
        "Split the two things down the middle: the drill for Kofi and the torch for Jess.",
        "drill>A & torch>B",
        WORKSHOP,
    ),
)

# -- counts ----------------------------------------------------------------------------------------

test_count = CASES.test(
    # _pair_of41r
    ("The pair of them to Mrs Khan, jug and magazine.", "jug>C & magazine>C", WARD),
    ("The trio of pens goes in the box.", "pen_black@box & pen_blue@box & pen_red@box", OFFICE),
    ("The trio of cups goes on the tray.", None, LAB),
    ("The pair of them to Mrs Khan, jug, magazine and pills.", None, WARD),
    # _all_n_of_them41r
    (
        "Marco's taking all six of them.",
        "plate_white>A & knife>A & lemon>A & salt>A & plate_blue>A & tongs>A",
        KITCHEN,
    ),
    (
        "Sam gets all five of them.",
        "pen_black>B & notebook>B & pen_blue>B & stapler>B & pen_red>B",
        OFFICE,
    ),
    ("Sam gets all four of them.", None, OFFICE),
    # _onto_with41r
    ("On the desk with the globe and the ruler.", "globe@desk & ruler@desk", CLASSROOM),
    (
        "Up on the rack with the pair of them, the white plate and the blue plate.",
        "plate_white@rack & plate_blue@rack",
        KITCHEN,
    ),
    ("Into Marco with the spoon and the bowl.", None, KITCHEN),
    # _only_one_anyway41r
    ("Lily can have the teddy, it's the only one anyway.", "teddy>A", NURSERY),
    ("Lily can have the block, it's the only one anyway.", None, NURSERY),
    # _one_and_one41r / _plain_simple41r
    ("Give Noah the globe, plain and simple.", "globe>B", CLASSROOM),
    ("One globe and one person in the room, so Noah gets it.", None, CLASSROOM),
    # _pair_listed41r
    ("The trio of them to Tom, tape, gloves and scanner.", "tape>B & gloves>B & scanner>B", DEPOT),
    ("The pair of them to Tom, tape, gloves and scanner.", None, DEPOT),
)

# -- corrections -----------------------------------------------------------------------------------

test_corr = CASES.test(
    # _cue_run41r
    ("Drill on the bench, oh no, hang about, to Kofi.", "drill>A", WORKSHOP),
    ("Jess is getting the torch, oh scratch that, it's Kofi who gets it.", "torch>A", WORKSHOP),
    ("Salt to Lena, oh wait, she wants the lemon instead.", "lemon>B", KITCHEN),
    ("Pills to Mrs Khan, oh no, hang about, Mr Lee.", "pills>B", WARD),
    # one cue the older rules read, naming what the request said: refused as before
    ("Pills to Mrs Khan, oh no, hang about, Mrs Khan.", None, WARD),
    ("Salt to Lena, oh, she wants the lemon instead.", None, KITCHEN),
    # _straight_to41r
    ("Magazine up on the trolley, no, straight to Mr Lee.", "magazine>B", WARD),
    ("Drill on the bench, no, directly to Jess.", "drill>B", WORKSHOP),
    # _the_one_for41r
    (
        "Tablets across to Mrs Khan, oh, silly me, Mr Lee's the one they're prescribed for.",
        "pills>B",
        WARD,
    ),
    ("The notebook goes to Sam, no hang on, it's Priya's.", "notebook>A", OFFICE),
    ("The notebook goes to Sam, no hang on, it's the desk's.", None, OFFICE),
    # _pronoun_again41r
    ("Lena gets the salt, no, she gets the lemon.", "lemon>B", KITCHEN),
    ("Mr Novak gets the salt, no, he gets the knife.", "knife>C", KITCHEN),
    ("Lena gets the salt, no, she's having the lemon.", "lemon>B", KITCHEN),
    ("Mr Novak gets the salt, no, she wants the knife instead.", None, KITCHEN),
    # _said_already41r
    ("Ruler for Zoe; sorry, I said that already, just the once.", "ruler>C", CLASSROOM),
    ("Sorry, I said that already.", None, CLASSROOM),
)


test_closers_and_words = CASES.test(
    # _just_those41r: "…, just that, nothing more for him", "…, only that"
    ("Mrs Khan's to have the jug, only that.", "jug>C", WARD),
    ("Mrs Khan's to have the jug or the magazine, just those.", None, WARD),
    # after a cue the closer corrects the request: not dropped
    ("The spanners to Jess, sorry, just the one.", None, WORKSHOP),
    ("The cups to Emma, no, just the one.", None, LAB),
    # _of_all41r: "last of all", "all morning"
    (
        "Drill on the bench first, then the torch in the locker, and last of all Jess gets the "
        "hammer.",
        "drill@bench ; torch@locker ; hammer>B",
        WORKSHOP,
    ),
    ("Emma's been after the banana all tray.", None, LAB),
    # _out_on41r: "X out on the desk"
    ("The globe and the ruler out on the desk, please.", "globe@desk & ruler@desk", CLASSROOM),
    ("The globe out on Zoe, please.", None, CLASSROOM),
    ("Leave the knife out on the counter.", "knife@counter", KITCHEN),
    ("Leave the knife out on Marco.", None, KITCHEN),
    # _one_going41r: "only the one X going spare"
    ("There's only the one jug going spare and it's Mrs Khan's.", "jug>C", WARD),
    ("There's only the one blanket going spare and it's Mrs Khan's.", None, WARD),
    # _let_use41r: "let P hold (play with, cuddle) X"
    ("Keep the drill away from Jess and let her hold the torch instead.", "torch>B", WORKSHOP),
    ("Let Ava play with the teddy.", "teddy>C", NURSERY),
    ("Let Ava play with the mat.", None, NURSERY),
    # _not_picky41r: "P's not fussy: <a choice offered to her>"
    (
        "Emma's not fussy: a cup for her, green or white, take your pick.",
        "cup_green>C | cup_white>C",
        LAB,
    ),
    ("Omar's not fussy: a cup for her, green or white, take your pick.", None, LAB),
)


test_corrected_then = CASES.test(
    # _corrected_then41r: the corrected request, then another clause after a semicolon
    (
        "Lena gets the salt, no, correction, she's having the lemon; the knife is Marco's.",
        "lemon>B & knife>A",
        KITCHEN,
    ),
    (
        "Lena gets the salt, no, correction, she's having the lemon; the knife is the counter's.",
        None,
        KITCHEN,
    ),
)


test_turned_down = CASES.test(
    # _turns_down41r: a person turning a thing down said as an idiom, beside a request
    ("Sam can do without the stapler, pass him the notebook.", "notebook>B", OFFICE),
    ("Lena's passing on the salt, give her the lemon.", "lemon>B", KITCHEN),
    ("No hammer for Jess, hand her the torch.", "torch>B", WORKSHOP),
    ("Emma can't stand the banana, give her the bowl.", "bowl>C", LAB),
    ("Mr Lee has no use for the magazine, take him the jug.", "jug>B", WARD),
    ("Ava isn't keen on the bib, give her the teddy.", "teddy>C", NURSERY),
    ("Sam can do without the stapler, pass him the stapler.", None, OFFICE),
    ("Sam can do without the stapler, pass it to him.", None, OFFICE),
    ("The desk can do without the stapler, pass Sam the notebook.", None, OFFICE),
    ("Sam can do without the stapler.", None, OFFICE),
    # _rather_than_first41r: "Rather than X, …", "… in place of X"
    ("Rather than the drill, hand Kofi the torch.", "torch>A", WORKSHOP),
    ("Emma gets the bowl in place of the spoon.", "bowl>C", LAB),
    ("Rather than the drill, hand Kofi the drill.", None, WORKSHOP),
    # _of_your_choosing41r: "a block of your choosing", "one or other of the blocks"
    ("Give Ava a block of your choosing.", "block_red>C | block_green>C", NURSERY),
    ("Give Ava one or other of the blocks.", "block_red>C | block_green>C", NURSERY),
    # _start_again41r: "…, let me start again (rephrase), <request>"
    ("Give Lena the salt, let me start again, pass Marco the tongs.", "tongs>A", KITCHEN),
    (
        "Hand the knife to Marco, sorry, let me rephrase, the knife goes to Lena.",
        "knife>B",
        KITCHEN,
    ),
    ("Give Lena the salt, let me start again, pass them to Marco.", None, KITCHEN),
    # _left_to_you41r: "any'll do"
    ("Give the notebook to Priya or Sam, any'll do.", "notebook>A | notebook>B", OFFICE),
    ("Give Sam the notebook, any'll do.", None, OFFICE),
    # _shared_out41r: "One book each for P and Q: …", "Share the books between P and Q: …"
    (
        "One book each for Noah and Zoe: the red one to Noah and the green one to Zoe.",
        "book_red>B & book_green>C",
        CLASSROOM,
    ),
    (
        "Share the books between Noah and Zoe: the red one to Noah and the green one to Zoe.",
        "book_red>B & book_green>C",
        CLASSROOM,
    ),
    (
        "Divide the spanners between them: the small one to Kofi and the large one to Jess.",
        "spanner_small>A & spanner_large>B",
        WORKSHOP,
    ),
    (
        "The cups are to be shared: the green one to Dana and the white one to Omar.",
        "cup_green>A & cup_white>B",
        LAB,
    ),
    (
        "One book each for Noah and Zoe: the red one to Noah and the green one to Mrs Ortiz.",
        None,
        CLASSROOM,
    ),
    (
        "Divide the spanners between them: the small one to Kofi and the drill to Jess.",
        None,
        WORKSHOP,
    ),
    (
        "The cups are to be shared: the green one to Dana and the white one to Dana.",
        None,
        LAB,
    ),
)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-41 (12r) steps taken out: each
    rule is what reads it."""
    # session 42 (12r): `_negated_then42r` reads "P can do without X, pass him Y" as well
    CASES.refused_without(
        (
            *_rewrites41r._STEPS41R_FIRST,
            *_rewrites41r._STEPS41R,
            _rewrites42r._negated_then42r,
            # session 43 (12r): its rules of the same families read these too
            *_rewrites43r._STEPS43R_FIRST,
            *_rewrites43r._STEPS43R,
            # session 44 (12r): its rules of the same families read some of these too
            *_rewrites44r._STEPS44R_FIRST,
            *_rewrites44r._STEPS44R,
            # session 53 (12s; at the merge): 'each and every / every last thing' said
            # 'everything' reads some of these too
            _rewrites53s._every_single53s,
            # session 44 (12s): 'last of all' said as 'lastly' reads these too
            _rewrites44s._after_end44s,
            # session 52 (12r): a share-out by a role the people share reads these too
            _rewrites52r._each_kind52r,
        ),
        monkeypatch,
    )


# -- refusals that name the readings, and two wrong readings of main refused -----------------------

REFUSED = [
    # a correction the speaker doubts: the people it could mean
    (
        "Give the jug to Mr Lee, no, hang on, the other one, or was it? Not sure now.",
        WARD,
        ("Person B", "Person C"),
    ),
    # a choice someone said and the speaker forgot: the objects of that kind
    ("Emma wants one of the cups, she said which but I forget.", LAB, ("cup_green", "cup_white")),
    (
        "Mia wants one of the boxes, I can't remember which.",
        DEPOT,
        ("box_small", "box_medium", "box_large"),
    ),
    # a choice offering some boxes twice and one once (main read every box)
    (
        "Put a box on the pallet, the small one or the large one.",
        DEPOT,
        ("box_small", "box_large", "box_medium"),
    ),
    # 'Q's the one' naming a person the reading gives nothing (main read salt>B)
    ("Salt to Lena, Mr Novak's the one.", KITCHEN, ("Mr Novak", "Lena")),
]


@pytest.mark.parametrize(("text", "scene", "readings"), REFUSED)
def test_refusals_name_the_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    """A doubted correction names each person, a forgotten choice each object of its kind, a
    choice offering a task twice the tasks it offers, "Q's the one" both people."""
    with pytest.raises(GroundingError) as refused:
        offline.parse_instruction(text, scene)
    for reading in readings:
        assert reading in str(refused.value)


@pytest.mark.parametrize(("text", "scene", "readings"), REFUSED)
def test_refusals_need_these_rules(
    text: str, scene: Scene, readings: tuple[str, ...], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without the session-41 (12r) refusals and checks each of these sentences is read, or
    refused without its readings: the rules are what refuse them so."""
    # session 42 (12r): `which_lost42r` names the readings of a forgotten choice too
    monkeypatch.setattr(
        offline,
        "_REFUSALS",
        tuple(
            r
            for r in offline._REFUSALS
            if r not in _rewrites41r.REFUSE41R
            and r is not _rewrites42r.which_lost42r
            # session 50 (lead): `forgot_which50l` names them too
            and r is not _rewrites50l.forgot_which50l
        ),
    )
    monkeypatch.setattr(
        offline, "_CHECKS", tuple(c for c in offline._CHECKS if c not in _rewrites41r.CHECK41R)
    )
    try:
        offline.parse_instruction(text, scene)
    except GroundingError as refused:
        assert not all(reading in str(refused) for reading in readings)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # every option said twice is the choice said twice: read as before
        (
            "Put a plate on the rack, the white one or the blue one.",
            "plate_white@rack | plate_blue@rack",
            KITCHEN,
        ),
        # 'Q's the one' of the person who gets it
        ("Tablets to Mr Lee, he's the one.", "pills>B", WARD),
        ("Mrs Khan's the one who gets the jug.", "jug>C", WARD),
    ],
)
def test_checks_leave_these_read(text: str, want: str, scene: Scene) -> None:
    """The checks refuse only what they say: these read as before."""
    assert_reads(text, want, scene)
