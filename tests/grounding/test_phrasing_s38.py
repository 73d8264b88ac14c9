"""Session-38 phrasings of issue 12 (engineer 12): blind36's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions
(docs/grounding.md, "Session 38 (engineer 12)"). Each rule with sentences it reads (which fail
with the rules taken out) and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites51s, normalise
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
from tests.grounding.test_phrasing_s33t import L24, T21, TWO

CASES = PhrasingCases()

# -- a text written without commas: a remark about the person (he's / she's …) run on after the
# request, a courtesy word before it or not; and the person's state opening it, then 'so' -------

test_run_on = CASES.test(
    ("crisps for bob please hes back from his darts match", "chips>B", TWO),
    ("give tom the tape cheers hes been out on the vans all day", "tape>B", DEPOT),
    ("the teddy to lily shes back from her swimming lesson", "teddy>A", NURSERY),
    ("jug for mrs khan when youre free shes been up all night with the wardens", "jug>C", WARD),
    ("bobs back from the allotment so the crisps to him", "chips>B", TWO),
    (
        "mias back from the canteen so the tape to her and the scanner to tom",
        "tape>A & scanner>B",
        DEPOT,
    ),
    ("emmas on a diet for the fun run so a banana to her", "banana>C", LAB),
    # a pronoun that cannot be the one person; two people before it; a remark that negates or
    # names more; a clause joined by 'when'; the state naming something of the scene; the request
    # after 'so' naming another person the pronoun may be
    ("crisps for bob please shes back from her darts match", None, TWO),
    ("crisps for bob and alice please hes back from his darts match", None, TWO),
    ("crisps for bob please hes not back from his darts match", None, TWO),
    ("give bob the crisps when hes back from his darts match", None, TWO),
    ("bobs back from the shelf so the red mug to him", None, CELL),
    ("carols back from the allotment so the red mug to her and the cup to alice", None, CELL),
    ("bobs back from the allotment so give the crisps to alice", None, TWO),
)

# -- wants closed by what made the person want it: a bare word in -ing (with what it was done
# with, 'all day'), or a race of theirs ----------------------------------------------------------

test_after_doing = CASES.test(
    ("Person B could do with the chips after abseiling with the scouts.", "chips>B", L24),
    ("Carol wants the apple after gardening all morning.", "apple>C", CELL),
    ("Tom is gasping for the tape after the egg-and-spoon race.", "tape>B", DEPOT),
    (
        "Bob could murder the cup after the charity fun run, and Alice wants the apple.",
        "cup>B & apple>A",
        CELL,
    ),
    ("Mr Novak wants the lemon after snorkelling.", "lemon>C", KITCHEN),
    # a verb of the grammar; a thing of the scene; two people; a surface; an order, not a want;
    # an event word (a time)
    ("Carol wants the apple after giving Bob the cup.", None, CELL),
    ("Carol wants the apple after cleaning the shelf.", None, CELL),
    ("Carol and Bob want the apple after gardening.", None, CELL),
    ("Carol wants the apple on the shelf after gardening.", None, CELL),
    ("Give Carol the apple after gardening.", None, CELL),
    ("Carol wants the apple after the meeting.", None, CELL),
    ("Carol wants the apple after the three races.", None, CELL),
)

# -- courtesies: ', so if you could', 'On behalf of our <group>,', ', the <trade> wants a tidy
# <surface>'; an aside of what the person is inside 'What P needs … is X' ------------------------

test_courtesies = CASES.test(
    ("Carol's after the apple before her pilates, so if you could, cheers.", "apple>C", CELL),
    ("Tom needs the tape before his long drive, so if you would.", "tape>B", DEPOT),
    ("On behalf of our knitting group, please give Alice the crisps.", "chips>A", TWO),
    ("On behalf of the bowls club, kindly pass Mr Lee the jug.", "jug>B", WARD),
    ("The stapler in the box, please, the cleaner wants a clear desk.", "stapler@box", OFFICE),
    ("Put the hammer on the locker, the inspector likes a tidy bench.", "hammer@locker", WORKSHOP),
    ("What Dana needs, being a marathon runner, is the banana.", "banana>A", LAB),
    ("What Bob wants, being a retired angler with a sweet tooth, is the cup.", "cup>B", CELL),
    # the group a person or thing of the scene; what the trade wants an object; the trade a person
    # of the scene; the aside naming something; two people
    ("On behalf of our Bob, give Alice the crisps.", None, TWO),
    ("The stapler in the box, please, the cleaner wants a clean pen.", None, OFFICE),
    ("The stapler in the box, please, the intern wants a clear desk.", None, OFFICE),
    ("What Bob wants, being a keen apple eater, is the cup.", None, CELL),
    ("What Bob and Carol want, being anglers, is the cup.", None, CELL),
)

# -- remarks about the person: what left them tired or thirsty, what they have on (and a drink
# they want first), a promise someone by their trade made them ----------------------------------

test_remarks = CASES.test(
    ("Water jug to Mrs Khan, her physio makes her thirsty.", "jug>C", WARD),
    ("Tom's after the gloves; the pub quiz wore him out.", "gloves>B", DEPOT),
    ("Give Noah the ruler, his spelling bee left him shattered.", "ruler>B", CLASSROOM),
    (
        "Dana needs the green cup, she's got her pottery class and wants a cuppa first.",
        "cup_green>A",
        LAB,
    ),
    (
        "Lena gets the lemon, she's got her dance rehearsal and needs a snack first.",
        "lemon>B",
        KITCHEN,
    ),
    ("Crisps to Bob please, the caretaker promised him some.", "chips>B", TWO),
    # a pronoun that cannot be the one person; two people; a thing of the scene in the remark; no
    # object asked for; the promise's maker a person of the scene
    ("Water jug to Mr Lee, her physio makes her thirsty.", None, WARD),
    ("Give Noah and Zoe the ruler, his spelling bee left him shattered.", None, CLASSROOM),
    ("Give Noah the ruler, the glue stick left him shattered.", None, CLASSROOM),
    ("Lena is here, she's got her dance rehearsal.", None, KITCHEN),
    ("Crisps to Bob please, Alice promised him some.", None, TWO),
    ("Tape for Mia, the driver promised her some.", None, DEPOT),
)

# -- pronouns and ellipsis: "… it …, the X, I mean", 'P was asking after X', ', the one with a …
# on the cover', "P's done with X, (he's …,) so it can go in S" ----------------------------------

test_pronouns = CASES.test(
    ("Ruth needs it, the thermometer, I mean, for the morning round.", "thermometer>A", WARD),
    ("Lena wants it now, the salt shaker, I mean, before the rush.", "salt>B", KITCHEN),
    (
        "Mrs Khan was enquiring after the blue blanket, the one with the ducks on the front.",
        "blanket_blue>C",
        WARD,
    ),
    ("Priya was asking after the notebook; take it over to her.", "notebook>A", OFFICE),
    (
        "Sam was asking about the stapler, the one with the sticker on the side.",
        "stapler>B",
        OFFICE,
    ),
    ("Noah's finished with the globe, so it can go on the shelf.", "globe@shelf", CLASSROOM),
    (
        "Dana's done with the green cup, she's off to a lecture, so it can go in the sink.",
        "cup_green@sink",
        LAB,
    ),
    # 'it' of an object already named; two people; the X no object; asking after a person; what is
    # pictured named in the scene; the remark's pronoun not the person; no surface after 'go'
    ("Give Mia the tape and it, the scanner, I mean, now.", None, DEPOT),
    ("Mia and Tom want it, the scanner, I mean, now.", None, DEPOT),
    ("Mrs Khan was asking after Mr Lee.", None, WARD),
    ("Sam was asking about the stapler, the one with the red pen on the side.", None, OFFICE),
    ("Noah's finished with the globe, she's off home, so it can go on the shelf.", None, CLASSROOM),
    ("Noah's finished with the globe, so it can go to Zoe.", None, CLASSROOM),
)

# -- splits: ', and then you're done (for the day)' closing, ', with X on S after that' as a last
# step ------------------------------------------------------------------------------------------

test_splits = CASES.test(
    ("The cup to Bob, and then you're done for the day.", "cup>B", CELL),
    ("Hand Ruth the pills, then you're finished for now, off you go.", "pills>A", WARD),
    (
        "Knife to Marco first, then the lemon goes to Lena, with the tongs on the rack after that.",
        "knife>A ; lemon>B ; tongs@rack",
        KITCHEN,
    ),
    (
        "Give Sam the stapler, with the red pen in the box afterwards.",
        "stapler>B ; pen_red@box",
        OFFICE,
    ),
    # nothing asked before it, or more asked after it; the X a person; the S an object
    ("And then you're done for the day.", None, CELL),
    ("Give Bob the cup, and then you're done for the day, then give Carol the apple.", None, CELL),
    ("Give Sam the stapler, with Priya in the box afterwards.", None, OFFICE),
    ("Give Sam the stapler, with the red pen in the black pen afterwards.", None, OFFICE),
)

# -- lower case: a habit ('like every time', 'as always') closing a want; 'for the <trade>'s
# <things>' closing a want ----------------------------------------------------------------------

test_lower = CASES.test(
    ("mrs khan wants the blue blanket for her knees like every time", "blanket_blue>C", WARD),
    ("tom needs the tape for his van same as always", "tape>B", DEPOT),
    ("zoe wants the globe for the stage managers paper props", "globe>C", CLASSROOM),
    ("omar needs the bowl for the window cleaners big bucket", "bowl>B", LAB),
    # two people; an order, not a want; the things named in the scene; the trade a person of the
    # scene
    ("mrs khan and mr lee want the jug like every time", None, WARD),
    ("give mrs khan the jug like every time", None, WARD),
    ("zoe wants the globe for the stage managers red book", None, CLASSROOM),
    ("zoe wants the globe for the teachers paper props", None, CLASSROOM),
)

# -- questions and what follows them: "He's just back from his <doing>", a sentence about someone
# by their trade, ', ready for P's tea', 'How about P gets X and Q the Y(, seeing as …)?' ---------

test_questions = CASES.test(
    ("Could Tom have the gloves? He's just back from his forklift training.", "gloves>B", DEPOT),
    ("Can Ruth have the jug? She's back from her sea shanty choir.", "jug>A", WARD),
    (
        "Could you put the tape on the belt? The courier likes his parcels there.",
        "tape@conveyor",
        DEPOT,
    ),
    (
        "Could the drill go on the bench? The electrician's van parks by there.",
        "drill@bench",
        WORKSHOP,
    ),
    (
        "Would you put the wipes on the mat, ready for Ava's bath after the party?",
        "wipes@mat",
        NURSERY,
    ),
    ("How about Marco gets the knife and Lena the lemon?", "knife>A & lemon>B", KITCHEN),
    (
        "How about Person A gets the bottle and Person B the chips, seeing as he asked first?",
        "bottle>A & chips>B",
        T21,
    ),
    # the doing of the other sex's pronoun; the trade a person of the scene, or their words naming
    # something; ready for a thing of the scene; 'how about' with no person
    ("Could Tom have the gloves? She's just back from her forklift training.", None, DEPOT),
    ("Could you put the tape on the belt? The driver likes his parcels there.", None, DEPOT),
    ("Could you put the tape on the belt? The courier likes the scanner there.", None, DEPOT),
    ("Would you put the wipes on the mat, ready for the teddy's bath?", None, NURSERY),
    ("How about the knife and the lemon?", None, KITCHEN),
)


def test_refused_without_the_rules(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 39's _run_on39 and _after_all39 (engineer 12) say _run_on38's and _after_doing38's
    # kinds more widely: taken out too; so do 12s's remarks said without punctuation (sessions 39
    # and 40) and purpose of up to four words (session 40)
    CASES.refused_without(
        (
            *normalise._STEPS38,
            *normalise._STEPS39,
            *normalise._STEPS39S_FIRST,
            *normalise._STEPS39S,
            *normalise._STEPS40S_FIRST,
            *normalise._STEPS40S,
            *normalise._STEPS41S_FIRST,
            # session 51 (12s): its run-on rule says these remarks with their stops too
            _rewrites51s._run_on51s,
        ),
        monkeypatch,
    )


def test_a_want_after_the_remark_is_a_second_request() -> None:
    # refused in session 38; read by session 45's rules (train 154257), as meant
    assert_reads(
        "crisps for bob please hes back from his darts match and wants the bottle too",
        "chips>B & bottle>B",
        TWO,
    )
