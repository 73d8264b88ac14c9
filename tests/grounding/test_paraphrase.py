"""The offline grounder on the paraphrase corpus (issue 12) and properties of how it reads."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import (
    CORPUS_DIR,
    PARTS,
    Corpus,
    Entry,
    Outcome,
    Score,
    format_scores,
    judge,
    load_corpus,
    offline_tree,
    parse_expectation,
    show_tree,
)
from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from hltl.grounding.tree import Group, Task
from hltl.world.scene import Scene
from tests.grounding.helpers import one_edits

ROOT = Path(__file__).resolve().parents[2]
CORPORA: dict[str, Corpus] = {p: load_corpus(ROOT / CORPUS_DIR / f"{p}.yaml", ROOT) for p in PARTS}
# refused although a person would read them (docs/grounding.md reports them)
KNOWN_MISSES = frozenset(
    {
        "Give Carl the chips",  # 'Carl' is a common word (a name), so it is not read as 'Carol'
        # blind3 (tuned on in session 5): 'Hnad' is one edit from 'hand' and from 'had'
        "Hnad Alice the red mug please",
        # blind3: steps after the 'or' of an 'either' could belong to it or come after it
        "Either put the cup on the shelf, or give it to Bob and then give Carol the apple",
        # blind4 (tuned on in session 6): a description before a colon ("something to drink:")
        # blind4: "<objects> will do for <person>"
        # blind5 (tuned on in session 7): a surface name used as the verb
        # causes8 (second batch): a swap as an alternative followed by more ("…, or the other
        # way round, and Carol the apple"): the swap is read only as the last words
        "Give Alice the cup and Bob the chips, or the other way round, and Carol the apple",
        # causes9 (session 9): a remark that names objects ("keeps losing pens") may ask for
        # them, so it is not dropped
        "Priya keeps losing pens so give her the stapler",
        # blind8 (tuned on in session 10): "the third" after "one box each" is the box the two
        # do not get; read as a share of the three it is not said which goes where
        "Tom and Mia, one box each; the third goes on the belt",
        # causes10: a remark or an aside naming an object ("upset about the cup", "who has the
        # knife") may ask for it or pick someone out by it, so it is not dropped
        "Bob is upset about the cup, so give him the apple",
        "Lena, who has the knife, wants the lemon",
        # blind9 (tuned on in session 11): corrections said three times over ("Jess - no, Kofi -
        # no, Jess after all"): which one stands is not read ("… Actually no, grandpa's right,
        # give it to him." reads since session 32, 12s: the statement keeps only whom it is about)
        "the drill goes to Jess - no, Kofi - no, Jess after all",
        # blind9: a long dictated run-on of remarks naming the people again and again ('her' is
        # Lily or Grandad?); "So the thing is Jess is up a ladder …" (a remark of several clauses)
        "ok so Lily's just woken up from her nap and she's starving and Grandad's going to feed "
        "her so if you could bring Grandad the bib and the beaker that would be amazing thanks",
        "So the thing is Jess is up a ladder fixing the light and she's going to need the "
        "flashlight and honestly the screws too so could you get both of those over to her",
        # causes11 (session 11): a plan naming an object the request does not ("to move the large
        # box") may ask for it
        "Tom wants to move the large box, can he have the gloves?",
        # blind13 / causes15: 'she won't need it' after two people: whose, and which 'it'
        "Priya's leaving, give her the notepad, and Sam can have the stapler, she won't need it",
        "Lena's off home, give her the lemon, and Marco can have the knife, she won't need it",
        # causes15: 'after those two' after three sentences of which the first two are meant
        # blind15 (tuned on in session 17) and causes17: kinds not met yet (docs/grounding.md,
        # "Session 17"): a remark before a pronoun request, 'them' for one person, 'each' with a
        # list after, 'one of the <description>', purposes ('to bang together', 'before
        # service'), comparatives ('the two smaller'), verbs the grammar lacks ('Tidy', 'Clear',
        # 'Load … up with'), 'one of the other two', "bring Grandad's X over to him" (no title)
        "Mia wants the tape, she's sealing boxes, and Tom wants the scanner, he's checking the "
        "load",
        "Oh dear, Ava's dropped her block again. Pop the red block back to her, there's a love.",
        "Both cups need to go in the sink before lunch",
        # blind16 (tuned on in session 18) and causes18: kinds not met yet (docs/grounding.md,
        # "Session 18"): idioms no kind lists ('Prithee … unto … Anon', 'Play on', 'Namaste.
        # Breathe in', 'omg bestie', 'If everyone could just wait a moment … is going to'), 'the
        # N things that aren't X' as a subject, 'namely', 'leave the X where it is' after a
        # correction, 'All three of the pens, …, into the box, that's the deliverable', 'going home
        # with P tonight', "Don't … instead, good!" (session 35: 'circling back … action getting',
        # gapping with a rest, and 'the other one' after 'can keep' read; session 36: 'If everyone
        # could just wait a moment, our robot here is going to …' reads)
        # blind17 (tuned on in session 19) and causes19: kinds not met yet (docs/grounding.md,
        # "Session 19"): greetings and openers naming a person or holding a held word ('Howzit,
        # Jess.', 'For the record, and with the greatest respect'), pirate and Singapore English
        # grammar ('be wantin'', 'Bottle is what Alice want', 'Bob want one'), appositions of
        # roles or things the scene lacks ('My client, Sam', 'the treasure, the teddy bear'),
        # 'do likewise with', comparatives ('lesser', 'smaller'), 'N deliveries' said after the
        # steps, fronted recipients ('Unto Person A the chips'), a surface alias used as a verb
        # ('Cart'), corrections with a remark ('it's been redirected'), 'One apiece' headers
        "Good morning, good morning! Before the next track, could our robot friend pop the "
        "lemon over to Mr Novak? Lovely stuff.",
        "Person A takes the cup, and then the apple follows it to the very same player!",
        "Sorry, the crisps go to Carol, but not the apple, sorry, please leave that one.",
        "Cart the grey blanket over to Mr Lee.",
        "Everything except the apple is going home with Person B tonight, folks!",
        # blind18 (tuned on in session 20): kinds not met yet (docs/grounding.md, "Session 20"):
        # the speaker as 'me' inside a remark, corrections said with a remark ('hold on, Mummy's
        # talking', 'Hang on, not the lemon, the salt'), passives and 'is wanting', 'she' resumed
        # after a name, sentences of a name or 'first' alone, 'any of … will do', 'both of them'
        # after a list, 'Each of them' / 'Something for both of them' headers, 'the pair', 'the
        # lot', 'the one pair', exclusions with 'apart from' / 'that isn't', 'Not P, mind, P',
        # pronouns across clauses ('once hes got them'), texting ('n', 'like right now'), a typo
        # in a two-word name, 'Lilly' (a name of its own), 'do the X for P'
        "Both of the blocks onto the high chair, please, before she throws them again.",
        "Give the sippy cup to Lilly.",
        "Is it okay to do the chips for Person A first and then the bottle for Person B?",
        # blind19 (tuned on in session 21): kinds not met yet (docs/grounding.md, "Session 21"):
        # greetings and asides taken for names or corrections, wants said through another
        # ('Carol says she'd love'), passives, 'he'/'she' across clauses, fragments and run-ons,
        # choice and count words ('Either cup will do', 'big or small', 'one to Kofi and one to
        # Jess'), exclusions and negation, corrections with remarks, typos in a remark
        "Jess needs some screws, give her the tin.",
        # blind21 (tuned on in session 23): refusals left (docs/grounding.md, "Session 23")
        "Zoe's done colouring her map and wants to check it against the globe. Put it in her "
        "hands.",
        "Grandad's got Lily on his knee with a messy face, hand him the wipes.",
        "Wipes to Grandad. Bib to Ava. She'll get it on Lily.",
        # blind22 (tuned on in session 24): refusals left (docs/grounding.md, "Session 24")
        "That bottle by the door, up on the shelf with it, there's a good chap.",
        "Any of the pens will do for Sam, as long as it writes on chalk-stripe.",
        "Give Bob a mug, but not the red one, that's the controller's and she's funny about it.",
        "knife on the worktop please, the guests want it by their bread",
        # blind23 (tuned on in session 25): refusals left (docs/grounding.md, "Session 25")
        "Sorry to be a pest, but could you pop the red mug on the counter for me, cheers, I'll "
        "be tuning this thing for another hour.",
        "Person B's been on about the chips all morning and Person A's parched, so the bottle's "
        "for her.",
        "Crisps up on the shelf, or rather, no, straight into Alice's hands, she's on after the "
        "interval.",
        # 'N items, both give P' stays refused (test_phrasing_s28s's near form "Two items, both
        # give Alice."; session 33, 12t)
        "Two items, both give Alice lah.",
        # a bare 'for Priya' after a placement stays refused (test_phrasing_s31's "Put the ruler
        # on the desk for Noah"; session 33, 12t)
        # blind24 (tuned on in session 26): refusals left (docs/grounding.md, "Session 26")
        "Apple to Person B, and the cup, that one's for Person A, she's been waiting.",
        "Teddy for Lily and wipes for Grandad, the baby's sticky again, ta.",
        # blind25 (tuned on in session 27): refusals left (docs/grounding.md, "Session 27")
        # blind26 (tuned on in session 28): refusals left at its one measurement (docs/grounding.md)
        "Person B would love the bottle after that long lecture on beetles, and Person A fancies "
        "the apple.",
        "Any book not yet on the bookshelf wants shelving.",
        # blind27 (tuned on in session 29): refusals left at its one measurement (docs/grounding.md)
        "Person A gets the bottle Person B gets the chips no need to wrap them the greengrocer "
        "says.",
        "Crisps on the shelf, please. Scratch that, the milkman says Bob wants them.",
        "Tom needs the glovrs, the pallets are splintery.",
        # blind29 (tuned on in session 31): refusals left at its one measurement (docs/grounding.md)
        "That bottle? Person A's. She left it here when she nipped out to the draper's.",
        # a time after the request puts it off (test_phrasing_s34's "Give Carol the apple after
        # her walk."; session 35, 12r)
        "A single bottle will do for Person A after her orienteering.",
        # blind30 (tuned on in session 32): refusals left at its one measurement (docs/grounding.md)
        "Both of the spanners, large and small, go away in the locker tonight.",
        # blind33 (tuned on in session 35): every refusal at its one measurement reads (session 35)
        # blind34 (tuned on in session 36): refusals left at its one measurement (docs/grounding.md)
        # blind35 (tuned on in session 37): refusals left at its one measurement (docs/grounding.md)
        # blind36 (tuned on in session 38): refusals left at its one measurement (docs/grounding.md)
        "Can Person B have the bottle, and what about the chips for Person A, is that alright?",
        # blind37 (tuned on in session 39): refusals left at its one measurement (docs/grounding.md)
        "Alice is happy with either the bottle or the crisps after her spinning wheel demo, "
        "hand her whichever.",
        "Lily's building a castle like the one at the fete, she can have either block, she's "
        "not fussy.",
        "Stand both of the blocks up on the high chair so Lily can see them from her paddling "
        "pool.",
        "Take the bottle over to Person B, oh silly me, he's not here, it's Person A who's "
        "about, so give it her.",
        "Lemon on the plate rack, no, sorry, the worktop, chef wants it for the fish.",
        "Why not give Person B the chips, he's done nothing but ferry deckchairs all day?",
        # blind38 (tuned on in session 40): refusals left at its one measurement (docs/grounding.md)
        "Omar needs the sponge to clean up after the moth trap.",
        "Give each of them something for the star gazing tonight: Alice the bottle, Bob the "
        "crisps.",
        "Two things for two people: Person A's the chips, Person B's the bottle, both off to "
        "pinochle.",
        "Person B gets the chips, leave the bottle where it is, he's got his own.",
        "Bottle up on the shelf, oh, hang on, I meant hand it to Person A.",
        "The applie goes on the shelf for now.",
        # blind39 (tuned on in session 41): refusals left at its one measurement (docs/grounding.md)
        "Ta ever so, Person B's been on the sackbut all morning and could murder that bottle.",
        "The bottle's a must for Person B after bocce, and Person A's set on the chips.",
        "The bottle, that's Person A's. The chips, Person B has those, he called them after "
        "the dulcimer.",
        "Person A's down for the chips. Person B? The bottle, he said, after the hornpipe.",
        "Sam can take whatever pen he likes so long as it isn't the red one, the etcher "
        "borrowed that.",
        "Tablets across to Mr Lee, oh, silly me, Mrs Khan's the one they're prescribed for, "
        "the crumhorn lady.",
        # blind40 (tuned on in session 42): refusals left at its one measurement (docs/grounding.md)
        "Omar's after a spoon to stir his tea. Could you get him one?",
        "Bob was on about crisps all through the ice show and Alice wants her bottle can you "
        "sort that",
        "Person A's walking the coast path later and a single bottle will see her through, the "
        "one you've got.",
        "Is there any way Person B could get the chips this side of lunch?",
        "Could Grandad have the red block for Lily's tower?",
        # blind41 (tuned on in session 43): refusals left at its one measurement (docs/grounding.md)
        "Sagrai, as Lezgian speakers put it, for taking the stapler over to Priya.",
        "After a morning on the piling rig, Bob's gasping and the water bottle would save his "
        "life.",
        "If nobody else has claimed the bottle, Person A would gladly take it off your hands.",
        "Person A's apple needs taking to her, and her bottle as well.",
        "The cup? That's Person B's. The apple? Person A's. Off they go to them.",
        "The scissors are Zoe's to borrow, and Noah's having the glue.",
        "Put Lily's sippy cup on the high chair for her.",
        "Set both of Lily's blocks up on her high chair.",
        "Persohn A left her bottle with you earlier; she'd like it returned.",
        "Is it possible to get Omar both his banana and a bowl for it?",
        # blind42 (tuned on in session 44): refusals left at its one measurement (docs/grounding.md)
        "Lena has lemon wedges to do for table six and nothing sharp to do them with; sort her "
        "out.",
        "Person B's finished his smocking so he can have the chips now, and the bottle goes to "
        "her.",
        "Person A gets her bottle first; once she's got it, it's the turn of Person B, who's "
        "waiting by the kerb for the chips.",
        "Tongs to Marco he's at the grill, the knife to Lena she's on lemons.",
        "He's got a twelve-hour stoker shift ahead, so Person B is to have the cup plus the chips.",
        "Person B's allergic to apples, so the rest of the things are his and that one stays.",
        "since he skipped lunch the crisps are bob's and the bottle is for alice who's been at "
        "the go club",
        "marco's plating up on blue so that plate's his and lena has the white",
        # blind43 (tuned on in session 45): refusals left at its one measurement (docs/grounding.md)
        # blind44 (tuned on in session 46): refusals left at its one measurement (docs/grounding.md)
        "Blue mug first, for Alice, as she's off bodging stools. After that the apple goes to Bob.",
        "Bottle goes to Person A the apple to Person B no rush the pipe fitter's only just started",
        "Lena first, she wants the white plate; the tongs can go on the worktop after.",
        "Kofi wants the tin of screws Jess wants the small spanner both now please the "
        "helmsman's boat won't fix itself",
        "Person A's on her way to water divining, so hand her the bottle or the chips, "
        "whichever's handier.",
        "Carol's allergic to apples, so it's the crisps for her instead.",
        "For Person A, anything going except the cup will do.",
        "Person A isn't hungry for the apple; the chips instead.",
        "Person A has given up chips for Lent, so the bottle only for her.",
        "Nothing for anyone but Person A: bottle to her.",
        "Person B isn't the one getting the bottle, it's Person A, she's got the long walk home.",
        "Mr Lee's tablets can wait till the doctor's round; for now just hand him the magazine.",
        "Marco doesn't want the lemon; salt, please.",
        "Zoe's finished cutting out, so no scissors, just pass her the glue stick.",
        "The wipes don't belong on the play mat; pop them on the high chair.",
        "Never mind the hammer where it is; it's the drill that wants to go on the workbench.",
        "notebook to priya thanks she has minutes to take",
        "The scannsr to Tom, he's got the barrow boy's pallets to do.",
        # blind45 (tuned on in session 47): refusals left at its one measurement (docs/grounding.md)
        "Person A is doing a damson jam tasting, so she's needing both drinking vessels, bottle "
        "and cup alike.",
        "Alice put in for the bottle and she's owed it, so it's hers; Bob can have the crisps "
        "for his trouble.",
        "Person A would like the apple; she'll be after the cup too, so both of them to her.",
        "Bottle's hers, Person A's, and the chips belong with that fellow by the hatch, Person "
        "B, so sort them out.",
        "That big spanner belongs in the foreman's hands, Kofi's, he's got the wheeler's axle to "
        "tighten.",
        "Person B's bottle is the first job. When he's got it, the apple for Person A, the "
        "pigman's niece.",
        "The black pen goes in the box it's Sam's filing day and the stapler to Priya",
        "With the sword swallower coming to supper, Person A is owed the apple and the chips both.",
        "Share things out fair as the toll keeper would: bottle goes Person A's way and chips go "
        "Person B's way.",
        "Carry it how you like, on a tray or in your grabber, so long as Person A ends up "
        "holding the bottle.",
        "Person A's picnic for the haymakers wants two bits, the bottle plus the chips, so ferry "
        "the pair over.",
        "Line up both blocks on the high chair so Lily can play her stacking game, red and green "
        "together.",
        "Bob's not after any mugs or the cup, he's packing for the pétanque trip: bottle, crisps "
        "and apple, please.",
        "Bob's off the bottle since the mead festival, so leave that and get him the crisps "
        "instead.",
        "Apple's spoken for by the rector, but Person B is free to pick one other thing, cup or "
        "chips or bottle.",
        "Chips aren't going to Person A this time round; Person B's turn, he won the spillikins.",
        "Person A's had her fill of water at the cha-cha social, so the bottle's for Person B.",
        "Never mind the glass, just take the bottle to Person A.",
        "Emma's fasting for the samba gala so she's having nothing, but Dana's peckish, so the "
        "banana goes to Dana.",
        "Lena's banned from sharp things after the sword swallower incident, so she gets the "
        "tongs and no knife.",
        "Ava's building a castle that has to be green, so leave the red block out of it and "
        "fetch her the green.",
        "Person B ordered the apple but changed his tune at the pétanque; chips for him instead.",
        "Mr Lee's done with temperatures for today; the thermometer ought to be with Mrs Khan, "
        "my slip.",
        "the visitor looks half starved after the minuet so banana to her",
        "Sam's got a notebokk to fill with the rector's notices, so pass it to Sam.",
        "Tom's shifting crates of mead and needs the work goves, chuck them his way.",
        "The treddy on the play mat for Lily.",
        # blind46 (tuned on in session 48): refusals left at its one measurement (docs/grounding.md)
        "The chips? That's Person A's lot. The bottle? Hers as well, she's running the sand "
        "castle contest.",
        "Person A asked for the bottle on her way in from the bonesetter, and Person B the chips.",
        "Emma's the visitor; she'd like a banana, can you bring her one?",
        "Sam's run out of ink marking up the chair bodger's invoices and needs a pen. The red "
        "one'll do.",
        "Person A wants the apple she's been on the pogo stick all morning so get it to her.",
        "Person A's doing her wordsearch she's parched bottle to her.",
        "Ruth's doing her rounds the thermometer's for her.",
        "Salt shaker to Mr Novak he's asked twice now and the blue plate is for Marco.",
        "Bib on the highchair. Lily's lunch is next.",
        "That one bag of chips is for Person B to share round at the rebec rehearsal.",
        "Person B gets the chips; leave the bottle, he drank his fill at the snowman competition.",
        "Person B has gone off chips since the limbo contest; it's the cup he's after.",
        "After the washerwoman's race, Person A wants nothing but the chips.",
        "Tom needs all the kit apart from the boxes and the gloves.",
        "Not the white plate, Lena wants the one on the rack.",
        "Noah can have the scissors for his snowflake cut-outs, but the glue's off limits, he "
        "made a mess last time.",
        "Lily's had enough of the red block; give her the teddy, not another block.",
        "Chips to Person B, oh wait, he's not peckish, so Person A gets them, and the bottle "
        "goes to Person B.",
        "the water jug on mr lee's locker please he's been coughing all night",
        "Give Person A the bottler now, her bodhrán lesson starts in five.",
        # blind47 (tuned on in session 49): refusals left at its one measurement (docs/grounding.md)
        "Alice is back from the pitch and putt she wants the bottle give it her",
        "The bottle is Person B's he asked earlier the chips are Person A's.",
        "Grandad's feeding Lily on the sofa. The bib. He needs it, hand it to him.",
        "if you're free alice is after the cup and bob fancies a handful of crisps",
        "cheers mate and could person b get the bottle over there",
        "after darning circle person a was asking for chips and person b for the bottle",
        "water jug onto the cart please ruth's going round with it",
        "Person A asked nicely for the cfhips, pass them over.",
        "Persogn B's throat is dry from all that shouting at twister, so the bottle please.",
        "Persoln A is calling from the hallway for the bottle.",
        # blind48 (tuned on in session 50): refusals left at its one measurement (docs/grounding.md)
        "Cup to Person A first, she's the palm reader at the fete. Then the apple. That one's "
        "Person B's.",
        "Person A gets the bottle and Person B gets the apple and they're both off to the willow "
        "weaving",
        "Bottle to Person A she's the scenery painter and after that the chips to Person B no "
        "hurry at all mate",
        "Here's the plan. The bottle. Person A. That's all.",
        "Chips to Person B first, he's been up a ladder as a bill sticker all day, and then the "
        "bottle over to Person A.",
        "Sponge in the sink to soak. The bowl goes on the tray after that. The embryologist "
        "likes things neat.",
        "The water jug for Mrs Khan. And put the thermometer on the locker. Both now.",
        "Bob says not the crisps, he's stuffed after the rag rugging social, the bottle's what "
        "he wants.",
        "Person A's already got a drink of her own, so it's Person B, not her, the bottle goes to.",
        "Don't you be hanging onto the bottle all afternoon, Person A's the one it goes to.",
        "No point the bottle sitting there gathering dust when Person A needs it for the willow "
        "weaving.",
        "The drill's no use to Jess now the holes are done, but the hammer is, so the hammer to "
        "Jess.",
        "Leave the bottle, no, on second thoughts, give it to Person A.",
        # blind49 (tuned on in session 51): refusals left at its one measurement (docs/grounding.md)
        "Person A. Back from the square dance. She needs the bottle. And the cup, she said.",
        "Chips to Person B first since he's got swing dance in ten minutes, bottle to Person A "
        "next, okay.",
        "Person B has been on the dawn chorus walk since five and he's starving so the chips for "
        "him.",
        "Omar's finished with the sponge, so into the sink with it, and after that the bowl goes "
        "across to him.",
        "The single apple we've got, to Person B, he's the understudy tonight and needs feeding.",
        "Give Person B all of it bar the chips, he's gone off them since the herdsman's barbecue.",
        "person b fancies the bottle after his epee bout cheers",
        "grandad wants the teddy bear for lilys bedtime story",
        "Persxon A wants the bottle after her water aerobics.",
        # blind50 (tuned on in session 52): refusals left at its one measurement (docs/grounding.md)
        "If you'd be so kind, lay the knife on the worktop, Marco's doing the lemons in a sec.",
        "Mr Lee's been on at me about his tablets since ten, and Mrs Khan's thirsty, so she wants "
        "the water jug.",
        "Alice is after the bottle for her open water swim. Bob, same deal with the crisps.",
        "Person A gets the apple as her bit of lunch, and the cup's Person B's, for his tea "
        "before senet.",
        "That bottle belongs to Person A and she'd like it back before her flint knapping class.",
        "bottle for Alice crisps for Bob that's your lot cheers",
        "Cup first, it's Person B's. Apple second, that one's Person A's, she's eating it on the "
        "boat.",
        "Person A gets the bottle first and after she's had it you take Person B the chips and "
        "then you can have a rest.",
        "Chips? Person B. Cup? Person A. He's got pachisi at three and she's got a tooth out.",
        "Right so what we'll do is Person A has the chips and Person B has the bottle and then "
        "we're sorted for the boomerang lot.",
        "Blue pen to Sam and the notepad to Priya she's got the etymology meeting at two.",
        "Teddy goes down on the play mat where she can reach. After that the bib to Lily, it's "
        "nearly lunch.",
        "Of the boxes, two go on the belt today: the small one and the medium one, the large "
        "stays put.",
        "Alice is off crisps this week, so it's the bottle she wants, not those.",
        "Person B's allergic to apples, so let him have everything else you've got.",
        "Person A doesn't eat chips, but any of the other three things will do her, your choice.",
        "The cup's not Person A's, it's meant for Person B, so hand it to him.",
        "Person A doesn't want any of the food, only the bottle, she's just had her dinner.",
        "It's not for me, love, the bottle's for Person A over there.",
        "Sam can't stand red ink, so one of the other pens for him, you decide which.",
        "Mr Lee has had his medication already; it's only the water jug he's after.",
        "Load the boxes on the belt except for the big one, that's waiting on the pallet.",
        "Lily's bored of the teddy, she wants the red block instead.",
        "Bob's waiting on his crispz, could you take them over.",
        "Person B's after the appled for his packed lunch.",
        "Those xchips on the side are meant for Person A.",
        "Grandad's got jam on his hands, get him the baby wipws.",
        # blind51 (tuned on in session 53): refusals left at its one measurement (docs/grounding.md)
        "Oh, and if it's no bother, the tongs to Lena, she's got the mixologist waiting at the "
        "pass.",
        "Sorry to nag, but Zoe still needs the glue stick for her crystal growing poster, could "
        "you?",
        "Please, when you've a minute, the torch over to Jess, cheers, the light's awful under "
        "that van.",
        "Person B skipped breakfast and is now eyeing up the chips like a hawk, so they'd better "
        "go to him.",
        "Person B's gasping, so he ought to have the bottle, and the chips can keep Person A "
        "going.",
        "Person A's first in the queue for the bottle, and once she's sorted, Person B's lined up "
        "for the chips.",
        "Mr Novak reckons his truffle pasta is crying out for the salt, while Marco's after the "
        "knife for the fillets.",
        "Person B's got the chips coming, so take them across, and after those the apple's his as "
        "well.",
        "The gloves are Tom's, he left them, bring them to him.",
        "the bottle needs to go up on the shelf and bob said hed have the crisps so they go to him",
        "cup over to person a the apple is for person b oh and the bottle goes to person a as well",
        "Lena's got a table of six the white plate to her please and the salt",
        "Jess has run out of screws. Kofi's going to need the big spanner for the axle. Off you "
        "go.",
        "Both pens that aren't on the desk, the black and the red, go in the box.",
        "Pick whichever box you like from the two that aren't on the pallet and set it on the "
        "belt.",
        "One thing for Person A, she doesn't mind what, just so long as it isn't the chips.",
        "Priya wants every pen bar the blue one, so the red and the black go to her.",
        "Leave the teddy bear, it's the bib Grandad's asking for, Lily's about to have her mashed "
        "carrot.",
        "Every tool and bit for Jess, apart from the drill and the torch, she's kitting out her "
        "van.",
        "person a has been on the go all afternoon and needs that bottle so over it goes",
        "Since he sat down Bob hasn't taken his eyes off the xrisps, so let him have them.",
        "Pirson A left her cup behind at lunch, could it go back to her.",
        "Persun A hasn't eaten since breakfast and would like the chips.",
        "Person A is off out, she'll want her bettle handed over before she goes.",
        "Sam's minuting the budget meeting and needs the notepsd for it.",
        "Marco's finishing the fish and wants the lrmon to squeeze over it.",
        "Any chance you could run the packing tape over to Mia for the pallets?",
        # blind52 (tuned on in session 54): refusals left at its one measurement (docs/grounding.md)
        "Kofi reckons he'll need the power drill to put up the shelving in the office.",
        "Person A's got nothing to drink; pass her the bottle and him the chips.",
        "Her bottle, Person A's. Fetch it for her please.",
        "The apprentice has the screws job; pass the tin to Jess.",
        "Person A's thirsty the bottle's hers and Person B's hungry give him the apple",
        "Person A put her hand up first, so the apple goes her way, and once she's sorted the "
        "bottle heads to Person B.",
        "The bottle Person A wants it now she's back from her ice bath",
        "Green cup: sink. White cup: Dana's. Spoon: Omar, he's stirring something.",
        "Small box onto the pallet medium box onto the belt leave the big box where it is it's "
        "fine",
        "Noah's the one for the ruler and Zoe for the scissors, plus the red book wants putting "
        "on the desk.",
        "Alice doesn't want the red mug, she's funny about it; the blue one's the one to take her.",
        "Bob's after the crisps, but leave the bottle, he's got his own.",
        "Person A wants anything except the apple, so give her the cup.",
        "Leave the jug, Mr Lee's got water; it's his tablets he's after.",
        "the red mug for carol and the blue one for bob since hes on the decaf",
        "person a keeps looking at the chips so shes having them",
        "bottle for person a please she has dabke tonight and forgot to drink",
        "poor mrs khan is shivering under one sheet so pass her the blue blanket",
        "jess says the small spanners the one she needs",
        "Alice's been on about the crizps all afternoon, let her have them.",
        "Pergon B says he'd quite like the chips now, if there's no rush elsewhere.",
        "Someone left the spojge soaking on the side, into the sink with it.",
        "Priya's stuck stapling by hand, take her the stzpler.",
        "Mia needs the Scahner for stock-take, over to her please.",
        # blind53 (tuned on in session 55): refusals left at its one measurement (docs/grounding.md)
        "The cup: Person B. The chips: same again, him as well.",
        "Person A's after the bottle for her flask, and for Person B, the chips, he skipped "
        "breakfast.",
        "That bottle there is Person A's, take it across to her.",
        "Mrs Khan's tablets are due, take them to her please, and her magazine as well.",
        "Tom's got a long drive ahead; the gloves are his, so pass them to him.",
        "The bottle for Person A, she's a ferry pilot, up at dawn, needs it now",
        "No water since lunch and Person A's flagging, the bottle, straight over to her, ta "
        "muchly.",
        "Person A's just back from veena practice and she's thirsty so the bottle please and "
        "quickly",
        "chips to Person A bottle to Person B no need to rush either way",
        "The red pen, give it to Priya. The notepad, give it to Sam. Stapler, leave it.",
        "Mr Lee needs the thermometer. Mrs Khan wants her magazine. Both now please.",
        "Person B can have the lot bar the cup, he never drinks from cups.",
        "Person B's off chips this week, so they go to Person A.",
        "shelf for the bottle pls somewhere the baby cant grab it",
        "tom needs gloves on for the loading and mia wants tape",
        "jess is on the hammer today so give her it, and kofi needs the big spanner",
        "Park the apple on the coubter out of Bob's reach, ta.",
        "Since she's peckish, the chipl should go over to Person A.",
        "Reward Person B with the applo, he's been brilliant.",
        "A drink for Person A, she's been talking for hours: the bobtle, please.",
        # blind54 (tuned on in session 56): refusals left at its one measurement (docs/grounding.md)
        "Oh go on, if you'd be so kind, pop the blue mug down on the counter for me, ta ever so.",
        "Sorry, I know you're rushed off your feet, but Bob's been waiting ages for the crisps, "
        "could you run them over, cheers.",
        "Khob khun, you're a marvel, and would the apple go across to Person B when it suits.",
        "If it isn't too much of a faff, hand the apple across to Person A, would you, there's a "
        "good robot.",
        "Hello, hello, sorry, me again, the bottle for Person B please, thanking you kindly.",
        "Sukriya, and while you're at it, one small favour: the chips to Person A and the bottle "
        "to Person B.",
        "Morning, and apologies for pestering, but the stapler's cluttering things up, would you "
        "drop it into the box, much appreciated.",
        "Dhanyawad, you're a lifesaver, Tom needs the packing tape, over to the driver with it "
        "please.",
        "Do me a kindness and lay the globe on the desk, Mrs Ortiz would be chuffed to bits.",
        "Alice has a hankering for the crisps, while Bob reckons the bottle would hit the spot.",
        "Emma's keen on the green cup for her tea, and the doctor could do with the spoon to stir "
        "hers.",
        "Priya needs the notepad for her one o'clock, she'd be ever so grateful.",
        "Mia's lost without the barcode scanner today, and Tom's hands are raw so he wants the "
        "work gloves.",
        "Mr Novak is wanting the salt shaker, he finds the soup a bit bland.",
        "Person A has put her name down for the cup, while Person B is the one with a craving for "
        "the apple.",
        "Person B? He's the sound mixer and he's after the bottle, so hand it over to him.",
        "The apple's meant for Person A, and so are the chips, she paid for them.",
        "Person B's the puppet maker; the chips are his, so take them across to him.",
        "Whose is that bottle? Person A's, she left it behind when she popped out, so carry it "
        "across to her.",
        "Person A and Person B: she gets the chips, he gets the bottle.",
        "Sam, the intern, has no pen. Give him the red one.",
        "Tom's loading up. The small box, then the medium one, onto the belt.",
        "Alice could use the apple. Oh, and Bob. For him it's the red mug, tea's brewing.",
        "Bottle to Alice to kick things off, and once that's sorted, run the crisps over to Bob.",
        "Apple for Person A, bottle for Person B, and throw in the chips for Person A while "
        "you're there.",
        "Person A's off to fire twirling after this so the bottle to her now and the chips to "
        "Person B after.",
        "Tongs to Marco, lemon to Mr Novak, he likes it in his water.",
        "Clear the floor for the mopping, would you: the bottle and the crisps, the pair, up onto "
        "the shelf.",
        "Person A's happy with any one of the four, she honestly doesn't mind which you bring.",
        "Something for both of them, then: Person A gets the bottle, Person B the cup.",
        "Whichever of the two is closest, the chips or the bottle, take it to Person B.",
        "Share them out so nobody's left empty-handed: chips for Person B, and Person A gets the "
        "bottle.",
        "Any spare cup, white or green, to Emma, she isn't fussy.",
        "One of the pens to Sam, any of the three will do.",
        "The small box and the medium one, both of them, onto the belt, Tom's waiting to tape "
        "them up.",
        "Mr Novak needs a plate, white or blue, whichever you lay a hand on first.",
        "A book for each child: Noah the red one, and the green one for Zoe.",
        "There's one bottle and one bag of crisps, both want to go up onto the shelf.",
        "Person B is packing the picnic basket, so he's to have all four things, every last one.",
        "Two things are on Person A's list, the apple and the cup, and nothing beyond that.",
        "Only the single cup, to Person B, he just needs the one.",
        "Both items are Person A's, so take the pair of them to her.",
        "Both of the things here, bottle and chips, belong with Person B, he's the mask maker.",
        "Hand out both things: chips for Person A, bottle for Person B.",
        "The pair of cups, green and white, into the sink for washing.",
        "Priya's clearing the desk, so the black, the blue and the red pen, all three, in the box "
        "they go.",
        "Mrs Khan's shivering under the one sheet, so bring her both blankets, blue as well as "
        "grey.",
        "The driver's about to load, so every one of the three boxes, small, medium and large, "
        "onto the belt.",
        "Both of the books, the red one as well as the green one, go to Mrs Ortiz, she's got "
        "marking to do tonight.",
        "Kofi needs the pair of spanners, small and large, for the bolts.",
        "Alice would like the crisps, though not the apple, she's not a fruit person.",
        "The bottle's not for Alice, it's for Bob, take it to him.",
        "The bottle goes to Person B, and don't let Person A talk you into it being hers.",
        "The cup holds no interest for Person B, it's the apple he's been eyeing, so give him "
        "that.",
        "Person A's off the chips this week, just give her the bottle.",
        "Give the chips to anyone but Person A.",
        "Person A wants the bottle, and no, she doesn't want anything else.",
        "Leave Person B out this time round; both the bottle and the chips are headed to Person A.",
        "Mr Lee wants a blanket but not the grey one, he swears it makes him itch, so the other.",
        "Lena's gone off the white plate for some reason, bring her the blue one instead.",
        "Not the red block for Lily, she keeps chewing it, give her the green.",
        "Jess could use the screws, but leave the hammer alone, she's got her own.",
        "The apple to Bob, no, sorry, I'm thinking of Carol, give it to her.",
        "Leave the bottle be, actually, on reflection, run it over to Person A.",
        "Chips to Person B, bottle to Person A, oh no, I've said it backwards, swap those round.",
        "Salt over to Marco, er, no, make that the lemon for him.",
        "Teddy on the high chair, no, wait, Lily naps on the play mat, so teddy goes there "
        "instead.",
        "Drill to Kofi, wait, Jess needs it more, give it to Jess.",
        "those crisps keep getting knocked over so stick them up on the shelf out of harms way",
        "person a has been waiting for the apple and person b for the cup so off you go",
        "can person a have the bottle shes got handbell ringing later",
        "sam wants the black pen for signing things",
        "lena needs the tongs for the salad and mr novak is after the salt shaker",
        "jess needs the torch to see under there and kofi wants the screws",
        "Is it alright if Person B helps himself to the chips, do you reckon, and could you take "
        "them?",
        "Can Jess borrow the small spanner, hers has gone walkabout?",
    }
)
# refused without all the readings the refusal should list (docs/grounding.md reports them)
KNOWN_UNCLEAR = frozenset(
    {
        # blind21 (tuned on in session 23)
        # blind22 (tuned on in session 24)
        # blind37 (tuned on in session 39)
        # blind38 (tuned on in session 40)
        # blind39 (tuned on in session 41)
        # blind40 (tuned on in session 42)
        # blind41 (tuned on in session 43)
        # blind42 (tuned on in session 44)
        "Pass it to her when you're done with that.",
        "Noah and Zoe were squabbling over a book; give him the one he wanted.",
        # blind43 (tuned on in session 45)
        # blind44 (tuned on in session 46)
        "The bottle goes to the one who asked. The chips stay put.",
        "Tom asked for a box. Bring him the one he used yesterday.",
        "Not the big box for Tom, the one he asked for this morning.",
        # blind45 (tuned on in session 47)
        "Hand Person A the one she was eyeing up during the knucklebones game.",
        "Noah and Zoe both stuck their hands up; give the scissors to the other one.",
        "Can you give the bottle to the one who was at the pétanque with me? I forget who.",
        # blind46 (tuned on in session 48)
        "Alice and Carol came in from the lantern parade; she asked for the cup, so give it to "
        "her.",
        "Give Person A the chips, no, hang on, the other one, the one she had at the chair "
        "bodger's.",
        # blind47 (tuned on in session 49)
        "noah wanted a book earlier the red or the green one dunno which",
        # blind48 (tuned on in session 50)
        "Priya asked ever so nicely for a pen, the black or the red, and I've gone and forgotten "
        "which, sorry.",
        "Person B was after something when he came by, the chips maybe, or the cup, it's gone "
        "from me now.",
        "tom wanted a box, small or medium, can't remember which",
        # blind49 (tuned on in session 51)
        # blind50 (tuned on in session 52)
        "Mr Novak's table. He asked for a plate. Which one, I can't remember. White or blue.",
        # blind51 (tuned on in session 53)
        # blind52 (tuned on in session 54)
        "Kofi wants a spanner. Which one, he did say. Lost it, sorry.",
        "Lena asked me for a plate, was it the white one or the blue one? I can't recall.",
        # blind53 (tuned on in session 55)
        "Emma or Dana, one of them asked for the white cup. Can't remember who. Sorry.",
        "Omar wants either the bansna or the spoon, he did say which but I've forgotten.",
        # blind54 (tuned on in session 56)
        "Emma and Dana were both over by the sink; give her the sponge.",
        "Jess wants a spanner. One of them. Which, she didn't say, and I asked her twice.",
        "Person B's after one of the snacks, the apple or the chips, he said which but I've clean "
        "forgot.",
        "The globe to Noah, or was it Zoe who asked, I've got them mixed up.",
    }
)
# measured once and reported (docs/grounding.md), not asserted: a blind part's misses, wrong
# groundings included, are the measurement, and the grounder is not tuned on it
# ("blind" was measured once in session 2, then its misses were fixed in session 3; "blind2"
# measured once in session 3, its misses fixed in session 4; "blind3" measured once in session
# 4, its misses fixed in session 5; "blind4" measured once in session 5, its misses fixed in
# session 6; "blind5" measured once in session 6, its misses fixed in session 7; "blind6"
# written in session 7 by another engineer, measured once, its misses fixed in session 8;
# "blind7" written in session 8 by another engineer, measured once, its misses fixed in
# session 9; "blind8" written in session 9 by another engineer, measured once, its misses met
# in session 10; "blind9" written in session 10 by another engineer, measured once, its misses
# met in session 11; "blind10" written in session 11 by another engineer, measured once in
# session 12, its misses met in session 12; "blind11" written in session 12 by another engineer,
# measured once at the end of session 12, its misses met in session 13: all asserted now;
# "blind12" written in session 13 by another engineer, measured once at the end of session 13,
# its misses met in session 14: asserted now; "blind13" written in session 14 by another
# engineer, measured once at the end of session 14, its misses met in session 15: asserted now;
# "blind14" written in session 15 by another engineer, measured once at the end of session 15,
# its misses met in session 16: asserted now; "blind15" written in session 16 by another
# engineer, measured once at the end of session 16, its wrong readings and most of its refusals
# met in session 17: asserted now, the rest in KNOWN_MISSES; "blind16" written in session 17 by
# another engineer, reviewed by a second one, measured once at the end of session 17, its
# refusals met by kind in session 18: asserted now, the rest in KNOWN_MISSES; "blind17" written
# in session 18 by another engineer, reviewed by a second one, measured once at the end of
# session 18, its refusals met by kind in session 19: asserted now, the rest in KNOWN_MISSES;
# "blind18" written in session 19 by another engineer, reviewed by a second one, measured once
# at the end of session 19, its wrong readings and refusals met by kind in session 20: asserted
# now, the rest in KNOWN_MISSES; "blind19" written in session 20 by another engineer, reviewed
# by a second one, measured once at the end of session 20, its wrong readings and refusals met by
# kind in session 21: asserted now, the rest in KNOWN_MISSES; "blind20" written in session 21 by
# another engineer, reviewed by a second one, measured once at the end of session 21, its
# refusals met by kind in session 22: asserted now, the rest in KNOWN_MISSES; "blind21" written in
# session 22 by another engineer, reviewed by a second one, measured once at the end of session 22,
# tuned on in session 23: asserted now, the rest in KNOWN_MISSES; "blind22" written in session 23
# by another engineer, reviewed by a second one, measured once at the end of session 23, tuned on
# in session 24: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind23" written in
# session 24 by another engineer, reviewed by a second one, measured once at the end of session 24,
# tuned on in session 25: asserted now, the rest in KNOWN_MISSES; "blind24" written in session 25
# by another engineer, reviewed by a second one, measured once at the end of session 25, tuned on
# in session 26: asserted now, the rest in KNOWN_MISSES; "blind25" written in session 26 by
# another engineer, reviewed by a second one, measured once at the end of session 26, tuned on
# in session 27: asserted now, the rest in KNOWN_MISSES; "blind26" written in session 27 by
# another engineer and committed alone, reviewed by a second one, measured once at the end of
# session 27, tuned on in session 28: asserted now, the rest in KNOWN_MISSES; "blind27" written
# in session 28 by another engineer and committed alone, reviewed by a second one, measured once
# at the end of session 28, its one wrong reading fixed and tuned on in session 29: asserted now,
# the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind28" written in session 29 by another engineer
# and committed alone, reviewed by a second one, measured once at the end of session 29, tuned on
# in session 30: asserted now, the rest in KNOWN_MISSES; "blind29" written in session 30 by
# another engineer and committed alone, reviewed by a second one, measured once at the end of
# session 30, tuned on in session 31: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR;
# "blind30" written in session 31 by another engineer and committed alone, reviewed by a second
# one, measured once at the end of session 31, tuned on in session 32: asserted now, the rest in
# KNOWN_MISSES; "blind31" written in session 32 by another engineer and committed alone,
# reviewed by a second one, measured once at the end of session 32, its one wrong reading fixed
# and tuned on in session 33: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR;
# "blind32" written in session 33 by another engineer and committed alone, reviewed by a second
# one, measured once at the end of session 33 (0 wrong), tuned on in session 34: asserted now, the
# rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind33" written in session 34 by another engineer and
# committed alone, reviewed by a second one, measured once at the end of session 34 (0 wrong), tuned
# on in session 35: asserted now, the rest in KNOWN_MISSES; "blind34" written in session 35 by
# another engineer and committed alone, reviewed by a second one, measured once at the end of
# session 35 (1 wrong, fixed), tuned on in session 36: asserted now, the rest in KNOWN_MISSES;
# "blind35" written in session 36 by another engineer and committed alone, reviewed by a second
# one, measured once at the end of session 36 (0 wrong), tuned on in session 37: asserted now,
# the rest in KNOWN_MISSES; "blind36" written in session 37 by another engineer and committed alone,
# reviewed by a second one, measured once at the end of session 37 (0 wrong), tuned on in session
# 38: asserted now, the rest in KNOWN_MISSES; "blind37" written in session 38 by another engineer
# and committed alone, reviewed by a second one, measured once at the end of session 38 (1 wrong,
# fixed), tuned on in session 39: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR;
# "blind38" written in session 39 by another engineer and committed alone, reviewed by a second
# one, measured once at the end of session 39 (0 wrong), tuned on in session 40: asserted now, the
# rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind39" written in session 40 by another engineer and
# committed alone, reviewed by a second one, measured once at the end of session 40 (0 wrong),
# tuned on in session 41: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind40"
# written in session 41 by another engineer and committed alone, reviewed by a second one, measured
# once at the end of session 41 (1 wrong, fixed), tuned on in session 42: asserted now, the rest in
# KNOWN_MISSES and KNOWN_UNCLEAR; "blind41" written in session 42 by another engineer and committed
# alone, reviewed by a second one, measured once at the end of session 42 (0 wrong), tuned on in
# session 43: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind42" written in session
# 43 by another engineer and committed alone, reviewed by a second one, measured once at the end of
# session 43 (1 wrong, refused since session 44), tuned on in session 44: asserted now, the rest
# in KNOWN_MISSES and KNOWN_UNCLEAR; "blind43" written in session 44 by another engineer and
# committed alone, reviewed by a second one, measured once at the end of session 44 (1 wrong,
# refused since session 45), tuned on in session 45: asserted now, the rest in KNOWN_MISSES and
# KNOWN_UNCLEAR; "blind44" written in session 45 by another engineer and committed alone,
# reviewed by a second one, measured once at the end of session 45 (1 wrong, read right since
# session 46), tuned on in session 46: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR;
# "blind45" written in session 46 by another engineer and committed alone, reviewed by a second
# one, measured once at the end of session 46 (1 wrong, read right since session 47), tuned on in
# session 47: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind46" written in
# session 47 by another engineer and committed alone, measured once at the end of session 47 (1
# wrong, refused since session 48), tuned on in session 48: asserted now, the rest in KNOWN_MISSES
# and KNOWN_UNCLEAR; "blind47" written in session 48 by another engineer and committed alone,
# measured once at the end of session 48 (2 wrong, refused or read right since session 49), tuned
# on in session 49: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind48" written in
# session 49 by another engineer and committed alone, measured once at the end of session 49 (1
# wrong, refused since session 50), tuned on in session 50: asserted now, the rest in KNOWN_MISSES
# and KNOWN_UNCLEAR; "blind49" written in session 50 by another engineer and committed alone,
# measured once at the end of session 50 (0 wrong), tuned on in session 51: asserted now, the rest
# in KNOWN_MISSES and KNOWN_UNCLEAR; "blind50" written in session 51 by another engineer and
# committed alone, measured once at the end of session 51 (0 wrong), tuned on in session 52:
# asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind51" written in session 52 by
# another engineer and committed alone, measured once at the end of session 52 (0 wrong), tuned on
# in session 53: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind52" written in
# session 53 by another engineer and committed alone, measured once at the end of session 53 (1
# wrong, refused since session 54), tuned on in session 54: asserted now, the rest in KNOWN_MISSES
# and KNOWN_UNCLEAR; "blind53" written in session 54 by another engineer and committed alone,
# measured once at the end of session 54 (1 wrong, read right since session 55), tuned on in
# session 55: asserted now, the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind54" written in
# session 55 by another engineer and committed alone, measured once at the end of session 55 (2
# wrong, one read right and one refused since session 56), tuned on in session 56: asserted now,
# the rest in KNOWN_MISSES and KNOWN_UNCLEAR; "blind55" written in session 56 by another engineer
# and committed alone, measured once at the end of session 56, not asserted)
MEASURED_ONLY: frozenset[str] = frozenset({"blind55"})
CASES = [(part, e) for part, c in CORPORA.items() if part not in MEASURED_ONLY for e in c.entries]


def test_corpus_sizes() -> None:
    assert len(CORPORA["heldout"].entries) >= 100
    assert len(CORPORA["tuning"].entries) >= 200
    assert len(CORPORA["blind"].entries) >= 100
    assert len({e.scene for e in CORPORA["blind"].entries}) >= 4
    assert len(CORPORA["blind2"].entries) >= 100
    assert len({e.scene for e in CORPORA["blind2"].entries}) >= 4
    assert len(CORPORA["blind3"].entries) >= 120
    assert len({e.scene for e in CORPORA["blind3"].entries}) >= 4
    assert len(CORPORA["blind4"].entries) >= 150
    assert len({e.scene for e in CORPORA["blind4"].entries}) >= 8
    assert len(CORPORA["blind5"].entries) >= 180
    assert len({e.scene for e in CORPORA["blind5"].entries}) >= 12
    assert len(CORPORA["blind6"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind6"].entries}) >= 12
    assert len(CORPORA["causes8"].entries) >= 150
    assert len(CORPORA["blind7"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind7"].entries}) >= 12
    assert len(CORPORA["causes9"].entries) >= 100
    assert len(CORPORA["blind8"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind8"].entries}) >= 12
    assert len(CORPORA["causes10"].entries) >= 80
    assert len(CORPORA["blind9"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind9"].entries}) >= 12
    assert len(CORPORA["causes11"].entries) >= 80
    assert len(CORPORA["blind10"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind10"].entries}) >= 12
    assert len(CORPORA["causes12"].entries) >= 60
    assert len(CORPORA["blind11"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind11"].entries}) >= 12
    assert len(CORPORA["causes13"].entries) >= 100
    assert len({e.scene for e in CORPORA["causes13"].entries}) >= 10
    assert len(CORPORA["blind12"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind12"].entries}) >= 12
    assert len(CORPORA["causes14"].entries) >= 140
    assert len({e.scene for e in CORPORA["causes14"].entries}) >= 10
    assert len(CORPORA["blind13"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind13"].entries}) >= 3
    assert len(CORPORA["causes15"].entries) >= 170
    assert len({e.scene for e in CORPORA["causes15"].entries}) >= 10
    assert len(CORPORA["blind14"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind14"].entries}) >= 3
    assert len(CORPORA["causes16"].entries) >= 170
    assert len({e.scene for e in CORPORA["causes16"].entries}) >= 10
    assert len(CORPORA["blind15"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind15"].entries}) >= 3
    assert len(CORPORA["causes17"].entries) >= 140
    assert len({e.scene for e in CORPORA["causes17"].entries}) >= 10
    assert len(CORPORA["blind16"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind16"].entries}) >= 3
    assert len(CORPORA["causes18"].entries) >= 150
    assert len({e.scene for e in CORPORA["causes18"].entries}) >= 10
    assert len(CORPORA["blind17"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind17"].entries}) >= 3
    assert len(CORPORA["causes19"].entries) >= 150
    assert len({e.scene for e in CORPORA["causes19"].entries}) >= 10
    assert len(CORPORA["blind18"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind18"].entries}) >= 3
    assert len(CORPORA["blind19"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind19"].entries}) >= 3
    assert len(CORPORA["blind20"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind20"].entries}) >= 3
    assert len(CORPORA["blind21"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind21"].entries}) >= 3
    assert len(CORPORA["blind22"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind22"].entries}) >= 3
    assert len(CORPORA["blind23"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind23"].entries}) >= 3
    assert len(CORPORA["blind24"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind24"].entries}) >= 3
    assert len(CORPORA["blind25"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind25"].entries}) >= 3
    assert len(CORPORA["blind26"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind26"].entries}) >= 3
    assert len(CORPORA["blind27"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind27"].entries}) >= 3
    assert len(CORPORA["blind28"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind28"].entries}) >= 3
    assert len(CORPORA["blind29"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind29"].entries}) >= 3
    assert len(CORPORA["blind30"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind30"].entries}) >= 3
    assert len(CORPORA["blind31"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind31"].entries}) >= 3
    assert len(CORPORA["blind32"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind32"].entries}) >= 3
    assert len(CORPORA["blind33"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind33"].entries}) >= 3
    assert len(CORPORA["blind34"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind34"].entries}) >= 3
    assert len(CORPORA["blind35"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind35"].entries}) >= 3
    assert len(CORPORA["blind36"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind36"].entries}) >= 3
    assert len(CORPORA["blind37"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind37"].entries}) >= 3
    assert len(CORPORA["blind38"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind38"].entries}) >= 3
    assert len(CORPORA["blind39"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind39"].entries}) >= 3
    assert len(CORPORA["blind40"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind40"].entries}) >= 3
    assert len(CORPORA["blind41"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind41"].entries}) >= 3
    assert len(CORPORA["blind42"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind42"].entries}) >= 3
    assert len(CORPORA["blind43"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind43"].entries}) >= 3
    assert len(CORPORA["blind44"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind44"].entries}) >= 3
    assert len(CORPORA["blind45"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind45"].entries}) >= 3
    assert len(CORPORA["blind46"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind46"].entries}) >= 3
    assert len(CORPORA["blind47"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind47"].entries}) >= 3
    assert len(CORPORA["blind48"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind48"].entries}) >= 3
    assert len(CORPORA["blind49"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind49"].entries}) >= 3
    assert len(CORPORA["blind50"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind50"].entries}) >= 3
    assert len(CORPORA["blind51"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind51"].entries}) >= 3
    assert len(CORPORA["blind52"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind52"].entries}) >= 3
    assert len(CORPORA["blind53"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind53"].entries}) >= 3
    assert len(CORPORA["blind54"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind54"].entries}) >= 3
    assert len(CORPORA["blind55"].entries) >= 200
    assert len({e.scene for e in CORPORA["blind55"].entries}) >= 3
    for part, corpus in CORPORA.items():
        if part in MEASURED_ONLY:
            continue  # a held-back part is measured, not asserted
        assert len({e.scene for e in corpus.entries}) >= 3
        assert any(e.want is None for e in corpus.entries)
        assert any(e.readings for e in corpus.entries)


@pytest.mark.parametrize(
    ("part", "entry"), CASES, ids=[f"{p}: {e.scene}: {e.text[:50]}" for p, e in CASES]
)
def test_entry_is_grounded_exactly_or_refused(part: str, entry: Entry) -> None:
    out = judge(entry, CORPORA[part].scenes[entry.scene], offline_tree)
    assert out.verdict != "wrong", f"{entry.text!r} grounded as {out.detail}"
    if entry.text in KNOWN_MISSES:
        assert out.verdict == "refused", "a known miss now grounds: drop it from KNOWN_MISSES"
        return
    if entry.text in KNOWN_UNCLEAR:
        assert out.verdict == "unclear", "a known refusal without readings changed: drop it"
        return
    assert out.verdict == "exact", f"{entry.text!r}: {out.verdict}: {out.detail}"


def test_expectation_notation() -> None:
    node = parse_expectation("cup>A & (mug_red@shelf ; chips>B)")
    assert node == Group(
        "and",
        (
            Task("deliver", "cup", "A"),
            Group("seq", (Task("place", "mug_red", "shelf"), Task("deliver", "chips", "B"))),
        ),
    )
    assert show_tree(node) == "cup>A & (mug_red@shelf ; chips>B)"
    for bad in ("cup>A & chips>B | apple>C", "cup>", "(cup>A", "cup A", "cup>A )"):
        with pytest.raises(ValueError):
            parse_expectation(bad)


def _cell() -> Scene:
    return CORPORA["tuning"].scenes["cell"]


ACCEPTED = [e for e in CORPORA["tuning"].entries if e.want is not None and e.scene == "cell"]
WRAPS = [
    "please {}",
    "{}, please",
    "could you {}?",
    "{}, thanks!",
    "hey, {} real quick",
    "{} if you can",
    "um, {}",
    "sorry to bother you, but {}",
    "{} when you get a sec",
    "I know you're busy, but {}",
]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(ACCEPTED), st.sampled_from(WRAPS))
def test_politeness_never_changes_the_meaning(entry: Entry, wrap: str) -> None:
    text = entry.text.rstrip(".!?")
    if text.lower().startswith(("could ", "can ", "would ", "will ", "may ")):
        return  # already a polite question; wrapping it again is not how people talk
    plain = parse_instruction(entry.text, _cell())
    try:
        wrapped = parse_instruction(wrap.format(text), _cell())
    except GroundingError:
        return  # a refusal is allowed; a different spec is not
    assert show_tree(wrapped) == show_tree(plain)


NAMES = ["bottle", "apple", "chips", "crisps", "Alice", "Carol", "shelf", "table", "counter"]


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(NAMES), st.data())
def test_a_typo_means_the_word_or_nothing(name: str, data: st.DataObject) -> None:
    """One edit away from a scene name: grounded as that name, or refused; never another."""
    typo = data.draw(st.sampled_from(one_edits(name.lower())))
    if name in ("Alice", "Carol"):
        text, right = f"give {typo} the cup", f"give {name} the cup"
    elif name in ("shelf", "table", "counter"):
        text, right = f"put the cup on the {typo}", f"put the cup on the {name}"
    else:
        text, right = f"give Bob the {typo}", f"give Bob the {name}"
    try:
        got = parse_instruction(text, _cell())
    except GroundingError:
        return
    assert got == parse_instruction(right, _cell()), f"{text!r} -> {show_tree(got)}"


@pytest.mark.parametrize("text", ["😀🍎", "Дай Алисе чашку", "🙂 🙂"])
def test_no_words_recognised(text: str) -> None:
    with pytest.raises(GroundingError, match="no words recognised"):
        parse_instruction(text, _cell())


def test_a_foreign_word_among_english_ones_is_refused() -> None:
    with pytest.raises(GroundingError, match=r"'Бобу' .* not a word the offline grounder reads"):
        parse_instruction("give Alice the cup and Бобу the chips", _cell())


def test_ambiguous_pronoun_lists_the_readings() -> None:
    with pytest.raises(GroundingError) as info:
        parse_instruction(
            "give Alice the cup and Carol the apple, then hand her the chips", _cell()
        )
    msg = str(info.value)
    assert "'her' is not resolved" in msg and "Alice" in msg and "Carol" in msg
    assert "Bob" not in msg


def test_shared_choice_gives_each_a_different_object() -> None:
    got = parse_instruction("Alice and Bob would each like a mug", _cell())
    assert isinstance(got, Group) and got.op == "or"
    ways = {
        frozenset((t.obj, t.target) for t in (c.children if isinstance(c, Group) else ()))
        for c in got.children
    }
    assert ways == {
        frozenset({("mug_red", "A"), ("mug_blue", "B")}),
        frozenset({("mug_blue", "A"), ("mug_red", "B")}),
    }


def test_counts_must_match_the_scene() -> None:
    with pytest.raises(GroundingError, match=r"the scene has 2 .*mug_blue, mug_red.*not 3"):
        parse_instruction("give Alice the three mugs", _cell())
    with pytest.raises(GroundingError, match="need a different one of mug_blue, mug_red"):
        parse_instruction("Alice, Bob and Carol each want a mug", _cell())


def test_a_common_word_is_not_a_typo_but_the_refusal_suggests_the_name() -> None:
    with pytest.raises(GroundingError, match=r"no object called 'hugs'.*did you mean 'mug'"):
        parse_instruction("give Alice the hugs", _cell())
    with pytest.raises(GroundingError, match=r"no person called 'Carl'.*did you mean 'Carol'"):
        parse_instruction("give Carl the chips", _cell())
    assert show_tree(parse_instruction("give Carol the botle", _cell())) == "bottle>C"


def test_questions_are_not_requests() -> None:
    with pytest.raises(GroundingError, match="is a question, not a request"):
        parse_instruction("Is the apple on the shelf?", _cell())


def test_the_table_reports_wall_and_cpu_medians() -> None:
    entry = Entry("cell", "give Bob the chips", parse_expectation("chips>B"))
    outs = (
        Outcome(entry, "exact", 3.0, "", 1.0),
        Outcome(entry, "wrong", 9.0, "chips>A", 2.0),
        Outcome(entry, "refused", 30.0, "error", 5.0),
    )
    table = format_scores([Score("part", outs)])
    assert table.splitlines()[0].endswith("| median ms | median CPU ms |")
    assert table.splitlines()[2] == "| part | 3 | 33.3 % (1) | 1 | 0 | 1 | 9.00 | 2.00 |"
