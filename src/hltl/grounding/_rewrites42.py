"""The grounder's rules of session 42, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _name, _objects_only, _only, _only_person
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites41 import _elided42, _person_ending41
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 42 (engineer 12): blind40's refusals by kind — wants said by an idiom, pronouns and
# possessives, courtesies and question forms. Each rule a closed family checked against the scene;
# a remark, purpose or aside beside the request is 12s's kind, negation, counts and corrections
# 12r's (each blind40 sentence of these kinds was made to read with the other kind cut off).


# -- a want said with the thing first, in a cleft ("It's the chips that Person A has her heart set
# on", "as for Tom, it's the tape he's short of", "The cup's what Person A is after", "What Mia's
# after is the scanner"): the want said plainly, 'P wants X' (the grammar read 'It's X that P
# wants' before; the idioms here end on their preposition). X objects of the scene only, P one
# person of it opening its clause, or 'he' / 'she' (after 'as for P,' the pronoun must fit P and is
# said as P; otherwise left for the grammar to resolve). After a request naming things, a cleft
# not opened by 'as for P' may add to it or correct it: left as it was (refused naming both)
_STRANDED42 = (
    r"(?: wants| needs| fancies| would like| 'd like|'d like| could do with| could use| would "
    r"love| asked for| has asked for|'s asked for| has been asking for|'s been asking for"
    r"|(?:'s| is| has been|'s been) (?:really |so |dead |rather |quite |very )?(?:after|hoping for|"
    r"set on|short of|in need of|keen on|angling for|pining for|dying for|desperate for|gasping "
    r"for|crying out for|asking for|waiting for|holding out for|longing for|itching for|hankering "
    r"after|hankering for)"
    r"|(?: has|'s)(?: got)? (?:his|her|their) (?:heart|sights|eye|eyes) (?:set )?on"
    r"|(?:'s| is) (?:having|getting|to have|to get)| gets| should get| should have)"
)
_PERSON42 = r"(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)"
_IT_CLEFT42 = re.compile(
    r"(?:^|(?<=[.;!?,:—–])\s*|(?<=\band )|(?<=\bbut )|(?<=\bso ))"
    r"(?P<asfor>as (?:for|to|regards) (?P<ap>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?),\s*)?"
    r"(?:it's|it is|'tis) (?:just |only |really )?(?P<x>(?:the|that|this|those|these|both) "
    rf"[a-z][a-z ]*?) (?:that |which )?{_PERSON42}(?P<v>{_STRANDED42})(?=\s*(?:[,.;!?]|$))",
    _F,
)
_WHAT_CLEFT42 = re.compile(
    r"(?:^|(?<=[.;!?,:—–])\s*|(?<=\band )|(?<=\bbut )|(?<=\bso ))"
    r"(?P<x>(?:the|that|this|those|these|both) [a-z][a-z ]*?)(?:'s| is| are|'re) (?:just |exactly "
    rf"|precisely |really )?what {_PERSON42}(?P<v>{_STRANDED42})(?=\s*(?:[,.;!?]|$))"
    r"|(?:^|(?<=[.;!?,:—–])\s*|(?<=\band )|(?<=\bbut ))what "
    r"(?P<p2>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)"
    rf"(?P<v2>{_STRANDED42}) (?:is|are) (?P<x2>(?:the|that|this|those|these|both) [a-z][a-z ]*?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _cleft_want42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the clefts above said as 'P wants X'."""
    low = text.lower()
    if "what " not in low and "it's " not in low and "it is " not in low and "'tis " not in low:
        return text
    if _NEGATED42.search(text):
        return text  # "It's the bottle Alice wants, not the crisps": 12r's contrast reads it
    for pattern in (_IT_CLEFT42, _WHAT_CLEFT42):
        for m in list(pattern.finditer(text))[::-1]:
            x, who = m["x"] or m["x2"], m["p"] or m["p2"]
            if x is None or who is None or not _objects_only(x, lexicon):
                continue
            said = who
            ap = m.groupdict().get("ap")
            if ap is None and _ids(text[: m.start()], lexicon, "object"):
                # after a request naming things, the cleft may add to it or correct it (session
                # 31's refusal, offline._CLEFT_AFTER31, names both): left to it
                continue
            if who.lower() in ("he", "she"):
                if ap is not None:
                    if not _only_person(ap, lexicon):
                        continue
                    (pid,) = _ids(ap, lexicon, "human")
                    if not _fit36(pid, who, lexicon):
                        continue
                    said = ap
            elif ap is not None or not _only_person(who, lexicon):
                continue
            said = said[:1].upper() + said[1:] if m.start() == 0 else said
            text = f"{text[: m.start()]}{said} wants {x}{text[m.end() :]}"
    return text


# -- a want said by what the thing would do for the person ("Person A is dying of thirst; that
# bottle would save her life", "Noah's stuck, the ruler would be a lifesaver for him", "Bob's
# flagging, the apple would hit the spot"): the thing for the one person named before it whom the
# pronoun (if any) may be, 'give P X'. X objects of the scene only; two people before it, a pronoun
# that fits neither, a past ('would have saved') stay refused
_WOULD_HELP42 = re.compile(
    r"(?:^|(?<=[.;:,—–])\s*|(?<=\band )|(?<=\bso ))(?P<x>(?:the|that|this|those|these) [a-z][a-z "
    r"]*?) (?:would|will|'d|'ll) (?:really |just |honestly |absolutely )?(?:save (?P<p1>her|his|"
    r"their) (?:life|lives|bacon|day)|make (?P<p2>her|his|their) day|do (?P<p3>her|him|them) "
    r"(?:a world of |a power of |the world of )?good|perk (?P<p4>her|him|them) up|hit the spot"
    r"(?: for (?P<p5>her|him|them))?|go down a treat(?: with (?P<p6>her|him|them))?|be a "
    r"(?:lifesaver|godsend|life saver)(?: (?:for|to) (?P<p7>her|him|them))?)"
    r"(?P<end>\s*[.!]*)(?=\s*$)",
    _F,
)


def _would_help42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the want above closing the instruction, said as 'give P X'."""
    if " would " not in text.lower() and "'d " not in text and " will " not in text.lower():
        return text
    m = _WOULD_HELP42.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    head = text[: m.start()]
    people = _ids(head, lexicon, "human")
    if len(people) != 1 or _ids(head, lexicon, "object") or _ids(head, lexicon, "surface"):
        return text
    (pid,) = people
    pron = next((g for g in m.groups()[1:8] if g is not None), None)
    if pron is not None and not _fit36(pid, pron, lexicon):
        return text
    return f"{head}give {_name(pid, lexicon)} {m['x']}{m['end'].strip() or '.'}"


# -- how much the person wants it, said against everyone else ("Person B needs that bottle more
# than anybody right now", "Mia wants the scanner more than anything", "Bob could do with the apple
# more than ever"): how much, not who else gets it; taken off after a want of one person of the
# scene naming objects only ('more than Bob' names someone: stays)
_MORE_THAN42 = re.compile(
    r"(?P<want>(?P<p>\b[A-Za-z][\w]*)(?: (?:really |so |badly )?(?:wants|needs|would like|could "
    r"do with|could use|fancies)|(?:'s| is) (?:after|desperate for|dying for|crying out for)) "
    r"(?P<x>(?:the|that|this|those|these|both) [a-z][a-z ]*?)) more than (?:anybody|anyone|"
    r"anything|ever|everyone|everybody|most|any of them)(?: else)?(?: in the (?:world|room|"
    r"place))?(?=\s*(?:[,.;!?]|$| right now| now| today| at the moment))",
    _F,
)


def _more_than42(text: str, lexicon: Lexicon) -> str:
    """Session 42: 'more than anybody' (above) taken off the want."""
    if "more than" not in text.lower():
        return text
    for m in list(_MORE_THAN42.finditer(text))[::-1]:
        if _person_ending41(text, m.end("p"), lexicon, pronouns=True) is None:
            continue
        if not _objects_only(m["x"], lexicon):
            continue
        text = text[: m.end("want")] + text[m.end() :]
    return text


# -- possession said to the cell is a handover to the owner (the lead's policy, session 42: three
# blind writers read it so): "The chips are person b's", "That bottle's hers, Person A's.",
# "Bottle, that's Person A's. Apple, Person B's.", "Whose are the chips? Person B's." — each said
# as 'X to P'. X one thing of the scene, P one person of it; several owners ("Jess's and Kofi's"),
# a negation ("aren't P's": 12r's), a thing the person already has ("…, she's got it") and a
# thing or owner the scene does not single out stay refused
_OWNER42 = r"(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)'s"
_THING42 = r"(?P<x>(?:(?:the|that|this|those|these) )?[A-Za-z][a-z]*(?: [a-z]+)?)"
_POSSESSION42 = re.compile(
    r"(?:^|(?<=[.;!?])\s+|(?<=\band )|(?<=\bbut )|(?<=, ))(?:(?P<whose>whose (?:is|are) "
    r"(?P<wx>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?)\?\s+)|"
    rf"{_THING42}(?:(?:'s| is| are|'re)(?: (?:his|hers|theirs),)?|,(?: (?:that's|that is|it's|it "
    r"is|those are|these are|they're|they are))?) )(?:(?:all |just )?(?:hers|his|theirs),\s*)?"
    rf"{_OWNER42}(?P<end>\s*(?:[.!;]|$))",
    _F,
)
_NEGATED42 = re.compile(r"n't\b|\b(?:not|never|no)\b", _F)
_HAND_IT42 = re.compile(r"\b(?:give|hand|pass|bring|take|send) (?:it|them)\b", _F)
_HAS_IT42 = re.compile(
    r"^\s*,?\s*(?:and |but )?(?:he|she|they)(?:'s|'ve| has| have)(?: already)?"
    r" got (?:it|them|one)\b",
    _F,
)


def _possession42(text: str, lexicon: Lexicon) -> str:
    """Session 42: whose the one thing is, said alone as a sentence (above), said as 'X to P'."""
    if "'s" not in text or _NEGATED42.search(text):
        return text  # a negation beside it ("…; the bottle isn't") is 12r's contrast
    for m in list(_POSSESSION42.finditer(text))[::-1]:
        if _HAND_IT42.search(text[m.end() :]):
            continue  # "The blue mug is Bob's. Give it to him.": session 37's rule reads it
        x = m["wx"] or m["x"]
        if x is None or not _objects_only(x, lexicon) or len(_ids(x, lexicon, "object")) != 1:
            continue
        if not _only_person(m["p"], lexicon) or _HAS_IT42.search(text[m.end() :]):
            continue
        if re.search(r"\b(?:not|n't|never|no)\b", m[0], _F):
            continue
        thing = x[:1].upper() + x[1:] if m.start() == 0 or text[m.start() - 1] in " " else x
        text = f"{text[: m.start()]}{thing} to {m['p']}{m['end']}{text[m.end() :]}"
    return text


# -- a thing the person left or lost, asked back for them ("Person B left his bottle here; could he
# have it back?", "Person A left that bottle behind at the bus stop; it's hers, so she ought to get
# it back", "Bob forgot his apple. He'll want it back."): 'give P the X' (session 11 and 40 read
# '…, give it back to him' after a comma). P one person of the scene opening the sentence, X one
# object of it, the pronoun one P may be; a place of the scene where it was left ('on the shelf')
# and another person named stay as they were
_LEFT_BEHIND42 = re.compile(
    r"^(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)(?: (?:has|had)|'s|'d)? (?:left|forgot|forgotten|"
    r"dropped|lost|misplaced|abandoned) (?P<poss>his|her|their|that|the|this) "
    r"(?P<x>[a-z]+(?: (?!(?:behind|"
    r"here|there|over|back|again|earlier|yesterday|this|at|on|in|by)\b)[a-z]+)?)"
    r"(?: (?:behind|here|there|over here|back there))?(?: (?:at|on|in|by) the [a-z]+(?: [a-z]+)?)?"
    r"(?: again| earlier| yesterday| this morning)?\s*[;,.:—–]\s*"
    r"(?:(?:it's|it is|that's|that is) (?:(?P<own>his|hers|theirs)|(?:his|her|their) own)"
    r"(?: after all)?,?\s*(?:so\s+)?)?"
    r"(?:(?P<s1>he|she|they) (?:ought to|should|must|needs to|need to|has to|have to|'d better|"
    r"had better|can|could|may|will want to|'ll want to|wants to|would like to|'d like to) "
    r"(?:get|have|take) it back|(?:could|can|may|might|would you let|will you let) (?P<s2>he|she|"
    r"they|him|her|them) (?:have|get|take) it back|(?:please )?(?:let (?P<s3>him|her|them) have it"
    r" back)|(?P<s4>he|she|they)(?:'ll| will| would|'d) (?:want|like) it back)"
    r"(?:,? please)?(?P<end>\s*[.!?]*)\s*$",
    _F,
)


_SEX42 = {"he": "m", "him": "m", "his": "m", "she": "f", "her": "f", "hers": "f"}


def _left_behind42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the thing left and asked back (above) said as 'give P the X'."""
    if " back" not in text.lower():
        return text
    m = _LEFT_BEHIND42.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    thing = f"the {m['x']}"
    if len(_ids(thing, lexicon, "object")) != 1 or not _objects_only(thing, lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon, "human")
    said = f"{m['poss']} {m['own'] or ''} {m['s1'] or m['s2'] or m['s3'] or m['s4']}"
    sexes = {_SEX42.get(w.lower()) for w in said.split()} - {None}
    if len(sexes) > 1 or not _fit36(pid, said, lexicon):
        return text  # 'his' and 'she' of one person: two people may be meant
    if _ids(text.strip()[m.end("x") :], lexicon) - {pid}:
        return text  # another person or a place of the scene named after it
    return f"give {m['p']} {thing}."


# -- the speaker confirming what was just said ("Bob? Bottle. For him, yeah, that one.", "Give
# Mrs Khan the magazine. Yes, for her, that one."): says nothing new; taken off when the request
# before it names one person the pronoun may be, and objects
_CONFIRM42 = re.compile(
    r"(?<=[.!?])\s+(?:(?:yes|yeah|yep|aye|right|that's right)[,.]?\s+)?(?:for|to) (?P<pron>him|her|"
    r"them)(?:[,.]?\s+(?:yes|yeah|yep|aye|right|that's right))?[,.]?\s+(?:that one|that's the one|"
    r"that's it|the one|that's right)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _confirm42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the confirmation above taken off."""
    if " one" not in text.lower() and "that's it" not in text.lower():
        return text
    m = _CONFIRM42.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    people = _ids(head, lexicon, "human")
    if len(people) != 1 or not _ids(head, lexicon, "object"):
        return text
    if not _fit36(next(iter(people)), m["pron"], lexicon):
        return text
    return head


# -- the order said by the people ("Start with Person B. He gets the chips. Person A after him,
# with the bottle.", "Begin with Mr Lee: he has the jug. Mrs Khan after him, with the magazine."):
# 'Start with P. He gets X' is 'First P gets X', and 'Q after him, with Y' is 'Then Q gets Y' —
# the pronoun after Q cannot be Q, so it is the one person named before whom it may be (two such
# people, or a pronoun that fits none, stay refused)
_START_WITH42 = re.compile(
    r"^(?:let's )?(?:start|begin|kick off) with (?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)\s*[.:;,]\s*"
    r"(?P<pron>he|she|they) (?P<v>gets|has|can have|is having|'s having|'s getting|is getting|"
    r"wants|needs)\b",
    _F,
)
_AFTER_HIM42 = re.compile(
    r"(?<=[.;!])\s+(?P<q>[A-Z][\w]*(?: [A-Za-z][\w]*)?) (?:after|next after|straight after|"
    r"following) (?P<pron>him|her|them),?\s+with (?P<y>(?:the|that|this|those|these|both) [a-z][a-z"
    r" ]*?)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _people_order42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the order said by the people (above)."""
    low = text.lower()
    if "with " not in low:
        return text
    m = _START_WITH42.match(text)
    if m is not None and _only_person(m["p"], lexicon):
        (pid,) = _ids(m["p"], lexicon, "human")
        if _fit36(pid, m["pron"], lexicon):
            v = (
                "gets"
                if m["v"].lower() in ("has", "can have", "is having", "'s having")
                else m["v"]
            )
            text = f"First {m['p']} {v}{text[m.end() :]}"
    m = _AFTER_HIM42.search(text)
    if m is None or not _only_person(m["q"], lexicon) or not _objects_only(m["y"], lexicon):
        return text
    (qid,) = _ids(m["q"], lexicon, "human")
    before = _ids(text[: m.start()], lexicon, "human") - {qid}
    if len(before) != 1 or not _fit36(next(iter(before)), m["pron"], lexicon):
        return text
    if not _ids(text[: m.start()], lexicon, "object"):
        return text
    return f"{text[: m.start()]} Then {m['q']} gets {m['y']}{m['end'].strip() or '.'}"


# -- a pronoun after 'so' is the one the clause before it is about ("… and mrs khan is bored so
# bring her the magazine", "Bob's back, so give him the apple"): the person opening that clause
# (after 'and', a comma or the start), when the clause names nothing else and the pronoun fits;
# an earlier person of another clause is not meant. Two people in the clause stay refused
_SO_PRONOUN42 = re.compile(
    r",?\s+so (?:(?:could|can|would) you |please |just )?(?P<v>bring|give|hand|pass|get|take|fetch"
    r"|grab) (?P<pron>him|her)\b",
    _F,
)


def _so_pronoun42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the pronoun above said as the person, and the clause about them, if joined by
    'and' to another person's, made a sentence of its own (as "Ruth needs the thermometer. Mrs
    Khan is bored, so bring her the magazine" is read)."""
    if " so " not in text.lower():
        return text
    for m in list(_SO_PRONOUN42.finditer(text))[::-1]:
        head = text[: m.start()]
        parts = re.split(r"([,;.!?:—–]\s*|\s+(?:and|but|while|whereas)\s+)", head)
        clause = parts[-1]
        words = clause.split(" ")
        who = next(
            (" ".join(words[:n]) for n in (2, 1) if _only_person(" ".join(words[:n]), lexicon)),
            None,
        )
        if who is None or _ids(clause, lexicon) != _ids(who, lexicon):
            continue
        if not _fit36(next(iter(_ids(who, lexicon))), m["pron"], lexicon):
            continue
        if len(_ids(head, lexicon, "human")) < 2:
            continue  # one person named: the grammar resolves it as before
        if len(parts) > 1 and parts[-2].strip().lower() == "and":
            head = "".join(parts[:-2]) + ". " + clause
        ask = re.sub(r"^,?\s+so\b", ", so", text[m.start() : m.start("pron")], flags=_F)
        text = f"{head}{ask}{who}{text[m.end('pron') :]}"
    return text


# -- 'it' said first and named after ("Person A mentioned she'd like it brought over, the bottle
# that is, before her practice", "Give it to Bob, that is, the apple"): the thing said in the
# place of the 'it' (one 'it' in the clause before it); X objects of the scene only
_THAT_IS42 = re.compile(
    r",\s*(?:(?P<x1>(?:the|that|this) [a-z][a-z ]*?),? that is|that is,? (?P<x2>(?:the|that|this) "
    r"[a-z][a-z ]*?))(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _that_is42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the thing named after 'it' (above) said in its place."""
    if "that is" not in text.lower():
        return text
    m = _THAT_IS42.search(text)
    if m is None:
        return text
    x = m["x1"] or m["x2"]
    if not _objects_only(x, lexicon):
        return text
    head = text[: m.start()]
    clause = re.split(r"[.;!?]\s+", head)[-1]
    its = list(re.finditer(r"\bit\b", clause, _F))
    if len(its) != 1 or _ids(clause, lexicon, "object"):
        return text
    at = len(head) - len(clause) + its[0].start()
    return f"{head[:at]}{x}{head[at + 2 :]}{text[m.end() :]}"


# -- courtesies opening the instruction, said by the speaker or a third party not in the scene:
# an apology ("Evening, and sorry about the racket from the handpan group next door:", "Pardon me
# for butting in on your game, but"), thanks ("With many thanks from all of us at the club:"),
# regards ("The topiarist next door sends her regards;"), a word of thanks glossed ("Tanemmirt,
# which is thanks in Tamazight, my first language."): each asks nothing; taken off when its words
# name nothing of the scene ('me' / 'us' / 'her' there is the speaker or the one who sends it, no
# recipient) and a request follows
_GREETING42 = r"(?:(?:good )?(?:evening|morning|afternoon)|hello|hi|hiya|hey|greetings)"
_COURTESY42: tuple[re.Pattern[str], ...] = (
    re.compile(
        rf"^(?:{_GREETING42},?\s+(?:and\s+)?)?(?:(?:so |terribly |awfully |very )?sorry|(?:my )?"
        r"apologies|apologies|pardon me|excuse me|forgive me|beg pardon|i beg your pardon) "
        r"(?:about|for) (?P<w>[^:;.!?]{1,80}?)(?:\s*[:;.!?—–]\s*|,\s*but\s+)",
        _F,
    ),
    re.compile(
        r"^(?:(?:with|and) )?(?:(?:many|much|warm|grateful|heartfelt|big|huge) )?(?:thanks|"
        r"thank yous|gratitude|love|regards|best wishes|greetings|cheers)(?: (?:in advance|again))?"
        r" from (?P<w>[^:;.!?]{1,80}?)\s*[:;.!—–]\s*",
        _F,
    ),
    re.compile(
        r"^(?P<w>(?:the|our|my|your|a|an) [a-z][a-z' ]{0,60}?|[A-Z][a-z]+(?: [A-Z][a-z]+)?) "
        r"(?:sends|send|says|passes on|passed on|sent) (?:(?:his|her|their|its|warm|kind|best|fond)"
        r" )?(?:regards|love|best|best wishes|thanks|apologies|greetings|hellos?|compliments)"
        r"(?: to you| to you all| to all)?\s*[:;.!—–]\s*",
        _F,
    ),
    re.compile(
        r"^(?P<w>[A-Za-z][\w'-]*(?: [A-Za-z][\w'-]*)?),\s*(?:which|that) (?:is|means|'s) "
        r"(?:thanks|thank you|thank you very much|cheers|hello|please|sorry)(?: in (?:[A-Z][a-z]+"
        r"))?(?:,\s*(?:my|our|his|her|their) (?:first|mother|home|native) (?:language|tongue))?"
        r"\s*[.;:!—–]\s*",
        _F,
    ),
)


def _courtesy42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the courtesies above taken off (a request left after them)."""
    for pattern in _COURTESY42:
        m = re.match(pattern, text)  # gated (session 53, 12p)
        if m is None or _ids(m["w"], lexicon) or not _ids(text[m.end() :], lexicon):
            continue
        rest = re.sub(r"^(?:now|so|anyway|right|ok|okay),?\s+", "", text[m.end() :], flags=_F)
        text = rest[:1].upper() + rest[1:]
    return text


# -- a request asked in a question form ("Could I trouble you to see that Bob gets the bottle?",
# "would you be good enough to see Person A gets the bottle?", "Is it too much bother to get
# Person A her bottle?", "Could Mr Novak trouble you for the salt shaker?"): said as 'could you
# …' / 'could P have X', which the grammar reads; 'see (that) P gets X' is 'make sure P gets X';
# 'from over there' (where the thing is, which the scene says) is taken off. A time by which it is
# wanted ('this side of lunch') stays refused, as session 32's 'before lunch' is
_ASK_FORMS42: tuple[tuple[re.Pattern[str], str], ...] = (
    (
        re.compile(r"\b(?:could|can|might|may) I (?:just )?(?:trouble|bother|ask) you to\b", _F),
        "could you",
    ),
    (
        re.compile(
            r"\b(?:is it|would it be|will it be) (?:too much|a lot|much) (?:of a )?"
            r"(?:bother|trouble|hassle|to ask)(?: for you)? (?:to|if you could)\b",
            _F,
        ),
        "could you",
    ),
    (
        re.compile(
            r"\b(?P<ask>could|can|would|will) (?P<who>[A-Z][\w]*(?: [A-Z][\w]*)?) "
            r"(?:trouble|bother) you for\b",
            _F,
        ),
        "{ask} {who} have",
    ),
    (
        re.compile(
            r"\b(?P<ask>(?:could|would|will|can) you)(?: be (?:good|kind) enough to| be so "
            r"(?:good|kind) as to)? (?:please )?see (?:that |to it that )?"
            r"(?=[A-Z][\w]*(?: [A-Z][\w]*)? (?:gets|has|receives)\b)",
            _F,
        ),
        "{ask} make sure ",
    ),
    (re.compile(r"\s+from over (?:there|here|yonder)(?=\s*(?:[,.;!?]|$))", _F), ""),
    # "While you're on your feet, would you …", "…, when you're passing": the hearer's chance to
    # do it, asking nothing of its own
    (
        re.compile(
            r"(?:^|(?<=[.;!?])\s*)(?:while|when|whilst|since) you(?:'re| are) "
            r"(?:on your feet|up|up and about|passing|going past|walking past|nearby|about)\s*,\s*"
            r"|,?\s+(?:while|when|whilst) you(?:'re| are) (?:on your feet|up|up and about|passing|"
            r"going past|walking past)(?=\s*[.!]*\s*$)",
            _F,
        ),
        "",
    ),
)


def _ask_forms42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the question forms above said plainly (who is asked is one person of the scene
    or 'you'; the rest is read by the grammar as before)."""
    for pattern, said in _ASK_FORMS42:
        for m in list(re.finditer(pattern, text))[::-1]:  # gated (session 53, 12p)
            groups = m.groupdict()
            who = groups.get("who")
            if who is not None and who != "you" and not _only_person(who, lexicon):
                continue
            out = said.format(**{k: v for k, v in groups.items() if v is not None})
            if m.start() == 0 or text[: m.start()].rstrip().endswith((".", "?", "!", ":", ";")):
                out = out[:1].upper() + out[1:]
            text = text[: m.start()] + out + text[m.end() :]
    return text


# -- a proposal asked as a question, then agreed to ("How would it be if Person B had the cup and
# Person A the apple? Do that, please.", "Shall the chips go to Person B, then? Yes, let's do
# that.", "What if Bob got the apple? Go ahead."): the proposal is the request. Without the assent
# after it, 'how would it be if …?' stays refused (it asks the hearer's view)
_ASSENT42 = re.compile(
    r"\?\s+(?:(?:yes|yeah|yep|ok|okay|right|good|great|go on)[,.!]?\s*)?(?:(?:let's|please|then|so)"
    r",? )?(?:do that|do it|do so|go ahead|go for it|make it so|that's the plan|that'll do)"
    r"(?:,? (?:please|then|thanks))?\s*[.!]*\s*$"
    r"|\?\s+(?:yes|yeah|yep|ok|okay)(?:,? please)?\s*[.!]*\s*$",
    _F,
)
_PROPOSAL42 = re.compile(
    r"^(?:(?:so|ok|okay|right|well),?\s+)?(?:how (?:would|will|'d) it be if|what if|how about if|"
    r"what about if|suppose|supposing|would it work if|would it be ok if|would it be okay if) ",
    _F,
)


def _proposal42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the agreed proposal (above) said as the request ('had' / 'got' of a person of
    the scene said 'gets')."""
    if "?" not in text:
        return text
    a = _ASSENT42.search(text)
    if a is None or "?" in text[: a.start()]:
        return text
    q = text[: a.start()]
    if not _ids(q, lexicon):
        return text
    q = re.sub(r",\s*then$", "", q, flags=_F)
    m = _PROPOSAL42.match(q)
    if m is not None:
        rest = q[m.end() :]

        def gets(x: re.Match[str]) -> str:
            return f"{x['p']} gets" if _only_person(x["p"], lexicon) else x[0]

        rest = re.sub(
            r"(?P<p>\b[A-Z][\w]*(?: [A-Z][\w]*)?) (?:had|got|took|received|were given|was given)\b",
            gets,
            rest,
        )
        return rest[:1].upper() + rest[1:] + "."
    if re.match(r"^(?:shall|should|can|could|will) ", q, _F):
        return q + "?"
    return text


# -- room asked for, then the thing put there ("is there room on the tray for the bowl, and could
# you put it there?", "Is there space in the box for the stapler? If so, pop it in."): 'could you
# put X on S?'; S one surface of the scene, X objects of it only
_ROOM_FOR42 = re.compile(
    r"(?:^|(?<=[.;!?:])\s*)is there (?:any |enough )?(?:room|space) "
    r"(?P<prep>on|in|inside|on top of) (?P<s>the [a-z]+(?: [a-z]+)?) for "
    r"(?P<x>(?:the|that|this|those|these|both) [a-z][a-z ]*?)"
    r"(?:\s*,?\s*and|\?\s*(?:if so|if there is|if yes),?)\s*(?P<ask>(?:(?:could|can|would|will) "
    r"you )?(?:please )?)(?:put|pop|place|set|stick) (?:it|them) (?:there|on it|in it|in there|on "
    r"there)(?:,? please)?(?P<end>\s*[?.!]*)",
    _F,
)


def _room_for42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the question above said as the placement."""
    if "room" not in text.lower() and "space" not in text.lower():
        return text
    m = _ROOM_FOR42.search(text)
    if m is None or not _only(m["s"], lexicon, "surface") or not _objects_only(m["x"], lexicon):
        return text
    ask = m["ask"] or ""
    verb = "put" if ask else "Put"
    end = m["end"].strip() or ("?" if ask else ".")
    said = f"{ask[:1].upper()}{ask[1:]}{verb} {m['x']} {m['prep']} {m['s']}{end}"
    return text[: m.start()] + said + text[m.end() :]


# -- 'one' standing for the kind just wanted ("Omar's after a spoon. Could you get him one?", "Bob
# needs a mug; bring him one, please"): 'a <kind>' said again in its place (the grammar reads 'a
# spoon' as any spoon of the scene); the kind one word or two naming objects of the scene only,
# the pronoun left to the grammar
_GET_ONE42 = re.compile(
    r"^(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)(?: (?:wants|needs|would like|'d like|could do with"
    r"|could use)|(?:'s| is) (?:after|looking for|wanting|in need of)) (?:a|an) (?P<x>[a-z]+(?: "
    r"[a-z]+)?)\b(?P<mid>[^.;!?]*[.;!]\s*)(?:(?:could|can|would|will) you )?(?:please )?(?:just )?"
    r"(?:get|bring|fetch|grab|find|give|hand|pass) (?P<pron>him|her|them) one(?:,? please)?"
    r"(?P<end>\s*[?.!]*)\s*$",
    _F,
)


def _get_one42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the want and the request for 'one' (above) said once, 'give P a <kind>' (said
    twice, the grammar would read two of them)."""
    if " one" not in text.lower():
        return text
    m = _GET_ONE42.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon) or _ids(m["mid"], lexicon):
        return text
    if not _fit36(next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon):
        return text
    for n in (2, 1):
        kind = " ".join(m["x"].split(" ")[:n])
        if _objects_only(kind, lexicon):
            art = "an" if kind[0] in "aeiou" else "a"
            return f"give {m['p']} {art} {kind}."
    return text


# -- 'so' run on without its comma in a text typed without stops ("person b has dibs on the cup
# so the apple goes to person a"): the comma put back before a clause opening with a thing of the
# scene and its verb, after a clause naming objects ("…, so the apple goes to person a" is read)
_SO_RUN_ON42 = re.compile(
    r"(?<=[a-z]) so (?=(?:the|that|this|those|these) [a-z][a-z ]*? (?:goes|go|can go|should go|"
    r"is going|'s going|are going|gets|can have)\b)",
    _F,
)


def _so_run_on42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the comma before 'so' (above) put back."""
    if " so " not in text.lower():
        return text
    for m in list(_SO_RUN_ON42.finditer(text))[::-1]:
        before = re.split(r"[,.;!?]", text[: m.start()])[-1]
        if not _ids(before, lexicon, "object") or not _ids(before, lexicon, "human"):
            continue
        text = f"{text[: m.start()]}, so {text[m.end() :]}"
    return text


# -- the person's own thing in their want ("Alice wants her bottle", "Tom's after his gloves",
# "person b needs his chips"): 'his' / 'her' / 'their' after the want of the one person it may be
# is theirs — the thing is named by its noun as 'the X' (the grammar had asked whose 'her' is
# when another person was named in the instruction); a pronoun that cannot be P is left alone
_OWN_THING42 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*)(?P<v> (?:wants|needs|would like|'d like|could do with|could use|"
    r"wants back|asked for|has asked for|misses)|(?:'s| is) (?:after|asking for|missing|"
    r"waiting for|looking for)) (?P<pron>his|her|their) (?P<x>[a-z]+(?: [a-z]+)?)\b",
    _F,
)


def _own_thing42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the possessive above said 'the'."""
    if not any(w in text.lower() for w in (" his ", " her ", " their ")):
        return text
    for m in list(_OWN_THING42.finditer(text))[::-1]:
        who = _person_ending41(text, m.end("p"), lexicon)
        if who is None or not _fit36(next(iter(_ids(who, lexicon))), m["pron"], lexicon):
            continue
        if not any(_objects_only(" ".join(m["x"].split(" ")[:n]), lexicon) for n in (1, 2)):
            continue
        text = f"{text[: m.start('pron')]}the{text[m.end('pron') :]}"
    return text


# -- where a thing is to go, said as what a person of the scene says ("mrs ortiz has asked for the
# scissors and says the globe can live on the shelf from now on", "Priya says the stapler should
# stay in the box"): the placement asked for, 'X can go on S' (the grammar reads 'X can go on S';
# 'live' / 'stay' / 'belong' there say the same of where it is put). X objects of the scene only,
# S one surface of it; a person where the surface goes, or a negation, stays refused
_SAYS_PLACED42 = re.compile(
    r"(?P<lead>^|\band |[,;]\s*(?:and )?|[.!]\s+)(?:(?P<p>(?!and\b)[A-Za-z][\w]*(?: [A-Za-z][\w]*)?"
    r"|he|she) )?(?:says|"
    r"said|reckons|thinks|tells me|told me) (?:that )?(?P<x>(?:the|that|this|those|these|both) "
    r"[a-z][a-z ]*?) (?P<modal>can|should|could|may|must|will|is to|are to|ought to) (?:live|go|"
    r"stay|sit|belong|be kept|be put|be left|be stored) (?P<prep>on|in|on top of|inside) "
    r"(?P<s>the [a-z]+(?: [a-z]+)?)(?: from now on| for good| permanently| from today)?"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _says_placed42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the placement said as what someone says (above) said as 'X can go on S'."""
    if not any(w in text.lower() for w in ("say", "said", "reckon", "think", "told", "tells")):
        return text
    m = _SAYS_PLACED42.search(text)
    if m is None or not _objects_only(m["x"], lexicon) or not _only(m["s"], lexicon, "surface"):
        return text
    if m["p"] is not None and m["p"].lower() not in ("he", "she"):
        if not _only_person(m["p"], lexicon):
            return text
    elif not m["lead"].strip().lower().endswith("and") and m["p"] is None:
        return text
    modal = "should" if m["modal"].lower() in ("is to", "are to", "ought to") else m["modal"]
    said = f"{m['x']} {modal} go {m['prep']} {m['s']}"
    lead = text[: m.end("lead")]
    if m["lead"].strip().lower() in ("and", ",", ";", ", and", "; and"):
        # a sentence of its own: joined by 'and' to a want, the grammar would read both things
        # as going there
        lead = text[: m.start("lead")].rstrip() + ". "
    if lead.strip() == "" or lead.rstrip().endswith((".", "!")):
        said = said[:1].upper() + said[1:]
    return f"{lead}{said}{text[m.end() :]}"


# -- the want of the one person opening the sentence, its subject left unsaid after 'and' ("Alice
# is parched and would kill for the water bottle", "Mrs Khan is cold and would love the blue
# blanket"): the person said again ('…, and Alice would kill for …', which the grammar and the
# older rules read); the words before the 'and' name nothing else of the scene
_ELIDED_WANT42 = re.compile(
    r"(?<=\w) and (?=(?:would|'d|could) (?:really |so |happily |just |dearly )?(?:kill for|die for|"
    r"love|like|murder|do with|use|go for) (?:the|that|this|those|these|both|a|an|some) )",
    _F,
)


def _elided_want42(text: str, lexicon: Lexicon) -> str:
    """Session 42: the person said again after 'and' (above)."""
    if " and " not in text.lower():
        return text
    m = _ELIDED_WANT42.search(text)
    if m is None:
        return text
    who = _elided42(text[: m.start()], lexicon)
    if who is None:
        return text
    return f"{text[: m.start()]}, and {who} {text[m.end() :]}"


# the normaliser's rewrites run before the session-41 ones (wired into normalise._STEPS19)
_STEPS42_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _elided_want42,
    _cleft_want42,
    _would_help42,
    _more_than42,
    _possession42,
    _left_behind42,
    _confirm42,
    _people_order42,
    _so_pronoun42,
    _that_is42,
    _courtesy42,
    _ask_forms42,
    _proposal42,
    _room_for42,
    _get_one42,
    _so_run_on42,
    _own_thing42,
    _says_placed42,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-41 ones)
_STEPS42: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-41 ones)
REFUSE42: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-41 ones)
CHECK42: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
