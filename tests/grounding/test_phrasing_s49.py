"""Session-49 phrasings of issue 12 (engineer 12): blind47's politeness and fillers, wants and
needs, pronouns and ellipsis and questions, each as a family (docs/grounding.md, "Session 49
(engineer 12)"). Each rule with sentences in other words and scenes it reads (refused on main and
with the rule taken out), and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites49, offline
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
)

# the example scenes blind47 uses
DUO, ONE, T21, T12, TWO, SQ, F41, F42, L44 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("2-2", "1-1", "2-1", "1-2", "two_arms", "4-4-square", "4-1", "4-2", "4-4-line")
)

# -- sympathy with a word the grounder does not know ('poor mite') (_poor49) -----------------------

POOR = PhrasingCases()
test_poor = POOR.test(
    ("Lily's grizzling for her teddy bear again, poor mite.", "teddy>A", NURSERY),
    ("Carol's after the apple, poor mite.", "apple>C", CELL),
    ("Give Lena the lemon, poor mite.", "lemon>B", KITCHEN),
    ("Mrs Khan would like the magazine, poor old duck.", "magazine>C", WARD),
    ("Give the cup, poor mite.", None, CELL),
    ("Bob wants the cup, poor Carol.", None, CELL),
)


def test_poor_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    POOR.refused_without((_rewrites49._poor49,), monkeypatch)


# -- 'seeing' alone opening a reason ('seeing she's asked twice') (_seeing49) ----------------------

SEEING = PhrasingCases()
test_seeing = SEEING.test(
    ("Could the bottle go over to Person A, seeing she's asked twice?", "bottle>A", ONE),
    ("Could Carol have the apple, seeing she's been waiting?", "apple>C", CELL),
    ("Pass Sam the stapler, seeing he's asked nicely.", "stapler>B", OFFICE),
    ("Could the cup go to Bob, seeing she's asked?", None, CELL),
    ("Give it to her, seeing she's asked.", None, CELL),
)


def test_seeing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SEEING.refused_without((_rewrites49._seeing49,), monkeypatch)


# -- 'sorting P out with the X' (_sort_out49) ------------------------------------------------------

SORT = PhrasingCases()
test_sort = SORT.test(
    ("Person B's thirsty, would you mind sorting him out with the bottle?", "bottle>B", DUO),
    ("Would you mind sorting Person A out with the chips?", "chips>A", DUO),
    ("Would you mind sorting Mrs Khan out with the magazine?", "magazine>C", WARD),
    ("Sort it out with Bob.", None, CELL),
    ("Sort the cup out with Bob.", None, CELL),
    ("Sort him out with the cup.", None, CELL),
)


def test_sort_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SORT.refused_without((_rewrites49._sort_out49,), monkeypatch)


# -- 'it's in P's way' closing a placing (_in_way49) -----------------------------------------------

IN_WAY = PhrasingCases()
test_in_way = IN_WAY.test(
    ("Would you set the bowl down on the tray, it's in Dana's way?", "bowl@tray", LAB),
    ("Put the red mug on the shelf, it's in Carol's way.", "mug_red@shelf", CELL),
    ("Would you put the knife on the rack, it's in Marco's way?", "knife@rack", KITCHEN),
    ("It's in Carol's way.", None, CELL),
)


def test_in_way_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    IN_WAY.refused_without((_rewrites49._in_way49,), monkeypatch)


# -- 'for that' closing a request after a remark (_for_that49) -------------------------------------

FOR_THAT = PhrasingCases()
test_for_that = FOR_THAT.test(
    (
        "Jess is putting up brackets, could you fetch Jess the power drill for that?",
        "drill>B",
        WORKSHOP,
    ),
    ("Carol's making tea, could you bring her the red mug for that?", "mug_red>C", CELL),
    ("Sam's stapling the minutes, pass him the stapler for that.", "stapler>B", OFFICE),
    ("Could you bring the red mug for that?", None, CELL),
    ("Could you fetch the power drill for that?", None, WORKSHOP),
)


def test_for_that_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FOR_THAT.refused_without((_rewrites49._for_that49,), monkeypatch)


# -- 'any objection to' / 'any chance of' before what to do (_objection49) -------------------------

OBJECTION = PhrasingCases()
test_objection = OBJECTION.test(
    ("Person B's hungry, any objection to giving him the chips?", "chips>B", T21),
    ("Any objection to handing Marco the knife?", "knife>A", KITCHEN),
    ("Got any objection to passing Sam the stapler?", "stapler>B", OFFICE),
    ("Any objection to the bottle?", None, CELL),
)


def test_objection_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OBJECTION.refused_without((_rewrites49._objection49,), monkeypatch)


# -- 'just one thing:' opening the request (_one_thing49) ------------------------------------------

ONE_THING = PhrasingCases()
test_one_thing = ONE_THING.test(
    (
        "Sorry, sorry, just one thing: Lena needs the tongs, if you'd be so kind.",
        "tongs>B",
        KITCHEN,
    ),
    ("Just one thing: Carol needs the apple.", "apple>C", CELL),
    ("Just one thing: Mr Lee needs the grey blanket.", "blanket_grey>B", WARD),
    ("One thing, the cup.", None, CELL),
)


def test_one_thing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ONE_THING.refused_without((_rewrites49._one_thing49,), monkeypatch)


# -- 'With thanks from X,' opening the request (_thanks_from49) ------------------------------------

THANKS_FROM = PhrasingCases()
test_thanks_from = THANKS_FROM.test(
    (
        "With many thanks from the teacher, the globe over to Zoe, please and thank you.",
        "globe>C",
        CLASSROOM,
    ),
    ("With many thanks from the nurse, the grey blanket over to Mr Lee.", "blanket_grey>B", WARD),
    ("With thanks from Ruth, the magazine to Mrs Khan, please.", "magazine>C", WARD),
    ("With warm thanks from Mrs Ortiz, the globe to Noah.", "globe>B", CLASSROOM),
    ("With thanks from the globe, the book to Noah.", None, CLASSROOM),
)


def test_thanks_from_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THANKS_FROM.refused_without((_rewrites49._thanks_from49,), monkeypatch)


# -- 'could really use the X after …' (_could_use49) -----------------------------------------------

COULD_USE = PhrasingCases()
test_could_use = COULD_USE.test(
    (
        "Er, sorry to be a bother, but Person B could really use the chips after his shift as a "
        "kilnman.",
        "chips>B",
        F41,
    ),
    ("Carol could really do with the bottle after her shift.", "bottle>C", CELL),
    ("Lena could really use the tongs after her shift as a cook.", "tongs>B", KITCHEN),
    ("Could use the bottle after the run.", None, CELL),
)


def test_could_use_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    COULD_USE.refused_without((_rewrites49._could_use49,), monkeypatch)


# -- 'I'd be ever so grateful if P got the X' (_grateful49) ----------------------------------------

GRATEFUL = PhrasingCases()
test_grateful = GRATEFUL.test(
    (
        "If it's no trouble at all, I'd be ever so grateful if Person A got the bottle.",
        "bottle>A",
        F42,
    ),
    ("I'd be ever so grateful if Mr Lee got the grey blanket.", "blanket_grey>B", WARD),
    ("I'd be really grateful if Mrs Khan were given the magazine.", "magazine>C", WARD),
    ("I'd be grateful if Mr Lee got it.", None, WARD),
    ("Bob would be grateful if Carol got the cup.", None, CELL),
)


def test_grateful_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GRATEFUL.refused_without((_rewrites49._grateful49,), monkeypatch)


# -- 'to pass the time' after a want (_pass_time49) ------------------------------------------------

PASS_TIME = PhrasingCases()
test_pass_time = PASS_TIME.test(
    ("Mrs Khan is keen to have the magazine to pass the time.", "magazine>C", WARD),
    ("Marco wants the knife to pass the time.", "knife>A", KITCHEN),
    ("Mrs Khan would like the magazine to while away the afternoon.", "magazine>C", WARD),
    ("Pass the time.", None, CELL),
)


def test_pass_time_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PASS_TIME.refused_without((_rewrites49._pass_time49,), monkeypatch)


# -- 'for the last of the Ns' (_last_of49) ---------------------------------------------------------

LAST_OF = PhrasingCases()
test_last_of = LAST_OF.test(
    ("Mia requires the packing tape for the last of the parcels.", "tape>A", DEPOT),
    ("Lena needs the tongs for the rest of the sausages.", "tongs>B", KITCHEN),
    ("Sam needs the stapler for the last of the reports.", "stapler>B", OFFICE),
    ("Priya wants the notebook for the rest of the meetings.", "notebook>A", OFFICE),
    ("Tom needs the gloves for the rest of the boxes.", None, DEPOT),
    ("Tom needs the work gloves for the last of the pallets.", None, DEPOT),
)


def test_last_of_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LAST_OF.refused_without((_rewrites49._last_of49,), monkeypatch)


# -- 'now she's up from her nap' (_up_from49) ------------------------------------------------------

UP_FROM = PhrasingCases()
test_up_from = UP_FROM.test(
    (
        "Is it all right for Lily to have her sippy cup now she's up from her nap?",
        "beaker>A",
        NURSERY,
    ),
    ("Could Ava have the green block now she's up from her nap?", "block_green>C", NURSERY),
    (
        "Is it all right for Grandad to have the bib now he's up from his lie-down?",
        "bib>B",
        NURSERY,
    ),
    ("Could she have the green block now she's up from her nap?", None, NURSERY),
)


def test_up_from_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    UP_FROM.refused_without((_rewrites49._up_from49,), monkeypatch)


# -- 'she's had nothing since …' saying why (_had_nothing49) ---------------------------------------

HAD_NOTHING = PhrasingCases()
test_had_nothing = HAD_NOTHING.test(
    ("Alice is after the crisps, she's had nothing since the cluedo tournament.", "chips>A", TWO),
    ("Bob's after the crisps, he's had nothing since the quiz.", "chips>B", CELL),
    ("Carol wants the apple, she's had nothing all morning.", "apple>C", CELL),
    ("Carol wants the apple, she's had nothing to do.", None, CELL),
)


def test_had_nothing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HAD_NOTHING.refused_without((_rewrites49._had_nothing49,), monkeypatch)


# -- 'the X is his / hers' closing (_theirs49) -----------------------------------------------------

THEIRS = PhrasingCases()
test_theirs = THEIRS.test(
    ("Person B hasn't eaten since breakfast; the chips are his.", "chips>B", T21),
    ("Carol's parched; the bottle is hers.", "bottle>C", CELL),
    ("The cup is his.", None, CELL),
)


def test_theirs_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THEIRS.refused_without((_rewrites49._theirs49,), monkeypatch)


# -- a count of minutes in a 'while' aside (_minutes49) --------------------------------------------

MINUTES = PhrasingCases()
test_minutes = MINUTES.test(
    (
        "Hiya, would it be at all possible to get the bottle over to Person A while she's having "
        "five minutes off from the devil sticks?",
        "bottle>A",
        T12,
    ),
    ("Could the bottle go to Carol while she's having ten minutes off?", "bottle>C", CELL),
    ("Could the bottle go to Bob while she's having ten minutes off?", None, CELL),
)


def test_minutes_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    MINUTES.refused_without((_rewrites49._minutes49,), monkeypatch)


# -- a second want joined by ', while', a closing 'having lost at …' (_while_want49, _having49) ----

WHILE_WANT = PhrasingCases()
test_while_want = WHILE_WANT.test(
    (
        "Person A's got her eye on the apple, while Person B is after the cup, having lost at "
        "kerplunk.",
        "apple>A & cup>B",
        SQ,
    ),
    ("Alice wants the cup, while Bob is after the apple.", "cup>A & apple>B", CELL),
    ("Alice wants the cup, while Dave is after the apple.", None, CELL),
)


def test_while_want_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHILE_WANT.refused_without((_rewrites49._while_want49, _rewrites49._having49), monkeypatch)


HAVING = PhrasingCases()
test_having = HAVING.test(
    ("Alice is after the cup, having lost at chess.", "cup>A", CELL),
    ("Lena wants the lemon, having finished the fish course.", "lemon>B", KITCHEN),
    ("Alice is after the cup, having lost the apple.", None, CELL),
)


def test_having_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HAVING.refused_without((_rewrites49._having49,), monkeypatch)


# -- 'Midway through X,' opening the request (_midway49) -------------------------------------------

MIDWAY = PhrasingCases()
test_midway = MIDWAY.test(
    (
        "Midway through pass the parcel, Person B put in a request for the bottle; Person A's "
        "request was the chips.",
        "bottle>B & chips>A",
        DUO,
    ),
    ("Halfway through the quiz, Bob asked for the apple.", "apple>B", CELL),
    ("Midway through the film, Carol put in a request for the cup.", "cup>C", CELL),
    ("Halfway through the cup, Bob asked for the apple.", None, CELL),
)


def test_midway_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    MIDWAY.refused_without((_rewrites49._midway49,), monkeypatch)


# -- what has left someone wanting (_left49) -------------------------------------------------------

LEFT = PhrasingCases()
test_left = LEFT.test(
    ("An hour on the bongos has left Person A gasping for the bottle.", "bottle>A", DUO),
    ("All that shouting has left Carol gasping for the cup.", "cup>C", CELL),
    ("Two hours of lifting have left Tom desperate for the gloves.", "gloves>B", DEPOT),
    ("The cup has left Bob desperate for the apple.", None, CELL),
)


def test_left_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEFT.refused_without((_rewrites49._left49,), monkeypatch)


# -- a missed meal before the want (_skipped49) ----------------------------------------------------

SKIPPED = PhrasingCases()
test_skipped = SKIPPED.test(
    (
        "Emma skipped lunch for the stonecarver's talk and would appreciate the banana.",
        "banana>C",
        LAB,
    ),
    ("Person B went without lunch and wants the chips.", "chips>B", T21),
    ("Sam skipped lunch for the audit and would appreciate the stapler.", "stapler>B", OFFICE),
    ("Dave skipped lunch and would appreciate the banana.", None, LAB),
)


def test_skipped_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SKIPPED.refused_without((_rewrites49._skipped49,), monkeypatch)


# -- 'the X is what P would like' (_what_wants49) --------------------------------------------------

WHAT_WANTS = PhrasingCases()
test_what_wants = WHAT_WANTS.test(
    (
        "Person A is craving the chips after leapfrog with the kids, and the bottle is what "
        "Person B would like.",
        "chips>A & bottle>B",
        T21,
    ),
    ("Alice wants the cup, and the apple is what Bob would like.", "cup>A & apple>B", CELL),
    ("Marco wants the knife, and the lemon is what Lena fancies.", "knife>A & lemon>B", KITCHEN),
    ("The apple is what Dave would like.", None, CELL),
)


def test_what_wants_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHAT_WANTS.refused_without(
        (_rewrites49._what_wants49, _rewrites49._after_pastime49), monkeypatch
    )


# -- 'after leapfrog' in a want said as a state now, or opening it (_after_pastime49) --------------

AFTER_PASTIME = PhrasingCases()
test_after_pastime = AFTER_PASTIME.test(
    ("After three rounds of twister Person B is in real need of the bottle.", "bottle>B", L44),
    ("Carol is craving the apple after netball with the girls.", "apple>C", CELL),
    ("After two hours of netball Carol is in real need of the bottle.", "bottle>C", CELL),
    (
        "After three nights on the ward Mr Lee is in real need of the grey blanket.",
        "blanket_grey>B",
        WARD,
    ),
    ("Mrs Khan is craving the magazine after physio with the nurses.", "magazine>C", WARD),
    ("Bob wants the apple after lunch.", None, CELL),
    ("After lunch, Bob wants the apple.", None, CELL),
    ("After the meeting Bob could have the apple.", None, CELL),
)


def test_after_pastime_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    AFTER_PASTIME.refused_without((_rewrites49._after_pastime49,), monkeypatch)


# -- 'hinting about the X', 'any chance he could have them' (_hinting49) ---------------------------

HINTING = PhrasingCases()
test_hinting = HINTING.test(
    (
        "Bob's been hinting about the crisps all morning, any chance he could have them?",
        "chips>B",
        TWO,
    ),
    (
        "Carol's been hinting about the apple all day, any chance she could have it?",
        "apple>C",
        CELL,
    ),
    ("Bob's been going on about the crisps, any chance he could have them?", "chips>B", CELL),
    ("Dave's been hinting about the crisps, any chance he could have them?", None, CELL),
)


def test_hinting_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HINTING.refused_without((_rewrites49._hinting49,), monkeypatch)


# -- 'P asks whether the X could go …' (_asks_whether49) -------------------------------------------

ASKS_WHETHER = PhrasingCases()
test_asks_whether = ASKS_WHETHER.test(
    (
        "Priya asks, very politely, whether the stapler could find its way into the box.",
        "stapler@box",
        OFFICE,
    ),
    ("Carol asks, ever so nicely, whether the cup could go on the shelf.", "cup@shelf", CELL),
    (
        "Lena asks, very politely, whether the salt could find its way onto the rack.",
        "salt@rack",
        KITCHEN,
    ),
    ("Carol asks whether the cup could go to Bob.", None, CELL),
    ("Dave asks whether the cup could go on the shelf.", None, CELL),
)


def test_asks_whether_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ASKS_WHETHER.refused_without((_rewrites49._asks_whether49,), monkeypatch)


# -- 'has had her heart set on', a 'Since she …,' before it (_heart_set49) -------------------------

HEART = PhrasingCases()
test_heart = HEART.test(
    (
        "Since she came in from the wormery, Person A has had her heart set on the bottle.",
        "bottle>A",
        ONE,
    ),
    ("Since he got back from the gym, Bob has had his heart set on the bottle.", "bottle>B", CELL),
    ("Since he came off shift, Marco has had his heart set on the knife.", "knife>A", KITCHEN),
    ("Marco has had his heart set on the knife.", "knife>A", KITCHEN),
    ("Since she got back, Bob has had his heart set on the bottle.", None, CELL),
)


def test_heart_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HEART.refused_without((_rewrites49._heart_set49,), monkeypatch)


# -- 'asking after it', 'That X over there,' (_asking_after49) -------------------------------------

ASKING_AFTER = PhrasingCases()
test_asking_after = ASKING_AFTER.test(
    (
        "That bottle over there, Person A's been asking after it since fly tying finished.",
        "bottle>A",
        T12,
    ),
    ("That apple over there, Carol's been asking after it all morning.", "apple>C", CELL),
    ("That knife over there, Marco's been asking after it.", "knife>A", KITCHEN),
    ("Carol's been asking after it.", None, CELL),
)


def test_asking_after_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ASKING_AFTER.refused_without((_rewrites49._asking_after49,), monkeypatch)


# -- 'Ever so sorry …' opening, in a one-person scene: 'Ever' is no stranger's name there
# (offline._stranger_dropped34s, a bug fix: 'Ever' is a listed first name) -------------------------

EVER_SO = PhrasingCases()
test_ever_so = EVER_SO.test(
    (
        "Ever so sorry to interrupt, but Person A is parched, so the bottle to her, please and "
        "thank you.",
        "bottle>A",
        T12,
    ),
    ("Ever so sorry to bother you, but could the bottle go to her?", "bottle>A", ONE),
    ("Ever so sorry, but Person A wants the bottle, give it to her.", "bottle>A", T12),
    ("Ever is thirsty, the bottle to her.", None, T12),
    ("Ever so thirsty, she is, the bottle to her.", None, T12),
)


def test_ever_so_refused_with_the_name(monkeypatch: pytest.MonkeyPatch) -> None:
    EVER_SO.refused_with(offline, "_next_word", lambda *_: "", monkeypatch)


# -- the thing an 'it' is, named after the request with 'I mean' (offline._cut_off's exemption
# _rewrites49.thing_named49) -----------------------------------------------------------------------

IT_I_MEAN = PhrasingCases()
test_it_i_mean = IT_I_MEAN.test(
    ("Hand it over to Person A, the bottle, I mean.", "bottle>A", T12),
    ("Give it to Person A, the bottle, I mean.", "bottle>A", T12),
    ("Pass it to Carol, the red mug, I mean.", "mug_red>C", CELL),
    ("Hand the chips to Person A, the bottle, I mean.", None, T12),
    ("Put it on the shelf, the apple, I mean.", None, CELL),
    ("Hand it over, the bottle, I mean.", None, T12),
)


def test_it_i_mean_refused_as_cut_off(monkeypatch: pytest.MonkeyPatch) -> None:
    IT_I_MEAN.refused_with(_rewrites49, "thing_named49", lambda _text: False, monkeypatch)
