# ruff: noqa: E501
"""The refusals' and checks' guards (made by python -m hltl.grounding.refusalguard --write)."""

from hltl.grounding.stepguard import Entry

GUARDS: dict[str, Entry | str] = {
    "derivation": "33d71a3257a14c08229c5a2993d046f656216b51af821a61",
    "hltl.grounding._rewrites40:posture_state40": (
        "6cf3b8d6a10b133f",
        (
            (),
            ("hanging", "hangs", "hung", "sat", "sits", "sitting", "standing", "stands", "stood"),
            True,
        ),
        (
            (
                "_POSTURE_STATE40",
                (
                    "pattern",
                    "(?:^|[,;:.!?—–-]\\s*|\\b(?:and|but|so|because|since|as)\\s+)(?P<x>(?:the|a|an|this|that|these|those|my|your|his|her|their|our) (?:[a-z]+ ){0,2}?[a-z]+)(?P<be>'s|'re| is| are| was| were)?(?: (?:still|already|just|now|all|currently|usually|normally|always))? (?P<v>standing|sitting|hanging|stands|sits|hangs|stood|sat|hung)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites40r:doubted_correction40r": (
        "749a66282f9669c2",
        ((), ("know", "not", "remember"), False),
        (),
    ),
    "hltl.grounding._rewrites40r:one_of_them40r": (
        "44349d5c48b95bce",
        ((), ("one of",), False),
        (),
    ),
    "hltl.grounding._rewrites40s:_owner40s": ("0dc938d10b4ba26f", ((), ("for h",), False), ()),
    "hltl.grounding._rewrites41l:_done41l": (
        "a5c568cd1f70b42e",
        ((), ("been", "was", "were"), False),
        (),
    ),
    "hltl.grounding._rewrites41l:_taken_back41l": (
        "206ec10f91280faf",
        (
            (),
            (
                "bored",
                "cooled o",
                "done with",
                "enough of",
                "fed up ",
                "finished with",
                "gone ",
                "got",
                "had it up to here with",
                "her appetite",
                "his appetite",
                "interest",
                "off the idea of",
                "over",
                "sick",
                "through with",
                "tired",
            ),
            True,
        ),
        (
            (
                "_TAKEN_BACK41L",
                (
                    "pattern",
                    "\\b(?P<who>he|she|they|(?:person|mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)(?:['’]s|\\s+(?:is|was|has|had|have|are|were))?\\s+(?:(?:so|totally|completely|well|really|just|now|already|all|rather)\\s+)*(?P<idiom>(?<=already )got|got(?= (?:it|them|that|those|the [a-z]+(?: [a-z]+)?) already\\b)|gone (?:right |completely )?off|gone (?:cold|sour) on|over(?! the moon\\b)|(?:sick|tired|bored) (?:of|with)|fed up (?:of|with)|through with|finished with|done with|had (?:quite )?enough of|had it up to here with|lost (?:interest|his appetite|her appetite) (?:in|for)|cooled (?:on|off on)|off the idea of)\\s+(?P<x>(?:the |that |those |his |her |their )?[a-z]+(?: [a-z]+){0,3}|it|them|that|those)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41r:_the_one_gets41r": (
        "569558ecc27a3047",
        ((" one",), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:doubted_correction41r": (
        "043372296d31fa6a",
        ((), ("or is it", "or was it", "quote", "remember", "sure"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:which_forgotten41r": (
        "b1b47032cf35f1d3",
        ((), ("one of the",), False),
        (),
    ),
    "hltl.grounding._rewrites41s:_has_it41s": ("e171ea5d278392d8", ((), (" has ",), False), ()),
    "hltl.grounding._rewrites41s:_the_one41s": (
        "e9010c3695d17c4a",
        ((), ("the one", "the person"), False),
        (),
    ),
    "hltl.grounding._rewrites42l:_dative_list42l": (
        "a9f6e2b9c1679457",
        ((" and ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites42r:maybe_it_was42r": (
        "cff17e74b5dfbb2b",
        ((), ("maybe", "perhaps"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:which_lost42r": (
        "50ce4b9346e7bf11",
        ((), (" but ", "the one"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:whoever_asked42r": (
        "8d3fdb4efc6cc7e8",
        ((), ("whichever", "whoever"), False),
        (),
    ),
    "hltl.grounding._rewrites42s:_elses_after42s": (
        "8d611722574b52f0",
        ((), (" after ", " following "), False),
        (),
    ),
    "hltl.grounding._rewrites43r:asked_before43r": (
        "7e514d4c8ee50c13",
        ((), ("before", "earlier", "last", "morning", "other day", "yesterday"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:meant_one_refused43r": (
        "df1ce99da2dd8d91",
        ((), (" know", "the one i", "the usual one"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_MEANT_ONE43R",
                (
                    "value",
                    "\"\\\\b(?P<said>(?:you know|you'll know) (?:the one|which one|which)(?: i mean| i'm on about| i want)?|the one (?:i mean|i'm on about|i'm thinking of)|the usual one)(?=\\\\s*[.!?,;]?\\\\s*$)\"",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites43r:which_person_lost43r": (
        "68cd31a1495c030a",
        ((), ("which", "who"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:whose_one43r": ("97f99a8bedc4d2ed", ((), ("the one",), False), ()),
    "hltl.grounding._rewrites44r:other_asked44r": ("7f17e5403cfa461f", ((), ("other",), False), ()),
    "hltl.grounding._rewrites44s:unseen_which44s": (
        "4714558335333531",
        ((), ("which",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:other_k45r": ("72021b8e83c6ba95", ((), ("other",), False), ()),
    "hltl.grounding._rewrites46r:doubt_at46r": ("cf9fbae143e0b8c4", ((), ("which",), False), ()),
    "hltl.grounding._rewrites46s:first_after46s": ("0e95c8a7f6ae0a48", ((), ("first",), False), ()),
    "hltl.grounding._rewrites46s:order_dropped46s": (
        "5a8660c3e3964314",
        ((), ("first",), True),
        (
            ("_FIRST46S", ("pattern", "\\b(?:first|firstly)\\b", 34)),
            (
                "_LATER46S",
                (
                    "pattern",
                    "\\b(?:then|next|second|secondly|afterwards|after that|lastly|finally|last)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46s:order_of_remark46s": (
        "1ebf3bc36d799da6",
        (
            (),
            (
                "after that",
                "after this",
                "afterwards",
                "finally",
                "lastly",
                "later",
                "next",
                "then",
            ),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_THEN46S",
                (
                    "value",
                    '"(?:then|next|afterwards|after that|after this|later|finally|lastly)(?!\'s|\\\\u2019s| is\\\\b| was\\\\b| has\\\\b)"',
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites46s:the_ordinal46s": (
        "1ca922d5b6dc1603",
        ((), ("second", "third"), True),
        (
            (
                "_THE_NTH46S",
                (
                    "pattern",
                    "\\bthe (?P<n>second|secondly|third|thirdly)\\b(?=\\s*(?:$|[,.;:!?]|(?:one |ones )?(?:goes|go|gets|is|'s|can|could|should|will|needs|wants|belongs|stays|sits|to|for|on|onto|in|into)\\b))(?P<after>.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46s:then_more46s": (
        "b898e694da36dca3",
        (
            (),
            (
                "after that",
                "after this",
                "afterwards",
                "finally",
                "lastly",
                "later",
                "next",
                "then",
            ),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_THEN46S",
                (
                    "value",
                    '"(?:then|next|afterwards|after that|after this|later|finally|lastly)(?!\'s|\\\\u2019s| is\\\\b| was\\\\b| has\\\\b)"',
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites47r:doubt_one47r": ("eef0e7a355bf1829", ((), ("one of",), False), ()),
    "hltl.grounding._rewrites48r:given_by48r": ("cd7e887351f1ba50", ((), (" by ",), False), ()),
    "hltl.grounding._rewrites48r:one_of_two48r": (
        "f6b4d6037335f843",
        ((), ("one of the pair", "one of the two"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:where_it_is48r": (
        "f1c87fbf999ce525",
        ((), ("'s", "it", "they"), False),
        (),
    ),
    "hltl.grounding._rewrites48s:_held_apposed48s": (
        "351d746ff09af922",
        ((), (" the ",), False),
        (),
    ),
    "hltl.grounding._rewrites49l:_lot_after_things49l": (
        "4bbc2b2d05a4fd32",
        ((), ("everything", "lot"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:settled_again49r": (
        "ff89f23066adeadf",
        ((), (", so ",), False),
        (),
    ),
    "hltl.grounding._rewrites49r:then_again49r": ("eada7b206cf1a5d8", ((), (" then",), False), ()),
    "hltl.grounding._rewrites49r:whoever_else49r": (
        "2e6fb3b56d4dacef",
        ((), ("whoever",), False),
        (),
    ),
    "hltl.grounding._rewrites49s:_has_now49s": ("ce80a566f2ac89e1", ((), (" now",), False), ()),
    "hltl.grounding._rewrites50:_who_asked50": (
        "ac64e7ee41198f92",
        (("Was it ", "Which "), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_checklist51": (
        "7c17e1ab8fb75fa0",
        ((), ("complete", "delivered", "done", "finished", "sorted", "ticked"), False),
        (),
    ),
    "hltl.grounding._rewrites51:_done_said51": (
        "c0610ee85c1cf5b6",
        (
            (),
            (
                "already ",
                "been ",
                "both",
                "handled",
                "it",
                "seen to",
                "sorted",
                "taken care of",
                "that",
                "the lot",
                "them",
                "this",
                "those",
            ),
            True,
        ),
        (
            (
                "_DONE_SAID51",
                (
                    "pattern",
                    "[,;.!?]\\s*(?:(?:and|but|so|oh|well|though)\\s*,?\\s+)?(?P<said>(?:(?:it's|that's|it is|that is|it has|it's all|that's all|it's been|that's been|they're|they've been|it was|all) (?:all |already |been |now )*(?:sorted|handled|taken care of|dealt with|seen to|sorted out)|(?:it's|that's|it has|that has|it is|that is|it was|that was|they've|they have) (?:all )?(?:been |already )+done|(?:I've|I have|I|we've|we have|we|I'll|I will|we'll|I'm going to|I can|let me|leave it, I'll) (?:already |just |quickly |now )*(?:done|did|do|sorted|sort|sort out|sorted out|handled|handle|seen to|see to|dealt with|deal with|taken care of|take care of|get|got|fetch|grab|grabbed) (?:it|that|them|this|those|that one|this one|the pair of them|both of them|the lot|both|it all|them both|it out|that out)(?: (?:myself|ourselves|out|already|now|for (?:him|her|them)))?))\\s*[.!]*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites51:_fibbing51": (
        "8e335f12c5abe8c7",
        ((" leg", " on", " up", "fibs", "ing", "porkies", "serious", "tales"), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_gone51": (
        "3012640aeced4a17",
        ((), (" off", " out", "away", "discharged", "gone", "left", "not "), False),
        (),
    ),
    "hltl.grounding._rewrites51:_habit51": (
        "7bb5f4e97a797ac6",
        (
            (
                "always",
                "generally",
                "likes to",
                "mostly",
                "normally",
                "often",
                "tends to",
                "typically",
                "usually",
            ),
            (),
            True,
        ),
        (
            (
                "_HABIT51",
                (
                    "pattern",
                    "^(?P<said>(?P<p>[A-Z]\\w*(?: [A-Z]\\w*)?) (?:usually|normally|generally|typically|always|often|mostly|tends to|likes to) (?:gets?|has|have|takes?|receives?|is given|gets given)) [^,;.!?]+[.!]?$",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites51:_has_it51": (
        "024603a1b90e2a6b",
        (
            (" given ", " got ", " gotten ", " had ", " has ", " have ", " received ", "'s had"),
            (),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites51:_one_object_twice51": (
        "2283ad80a33d4dfc",
        ((" got", " had", " has"), (), True),
        (("_HOLDS51", ("pattern", "(?:'s got|'s had| has got| has had| has| had| got)\\b", 32)),),
    ),
    "hltl.grounding._rewrites51:_possibly51": (
        "df4028e3043adf72",
        ((), ("conceivably", "possibly", "potentially"), False),
        (),
    ),
    "hltl.grounding._rewrites51:_praise51": ("a205364b27419a7f", ((), ("ing",), False), ()),
    "hltl.grounding._rewrites51:_received51": (
        "66d6835e0bc62cc1",
        ((" been ", " collected ", " got hold ", " picked up ", " received "), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_they51": ("b3ea19fc9f100743", ((), ("they",), False), ()),
    "hltl.grounding._rewrites51:_want_now51": (
        "459a07fc60f09665",
        (("this time",), ("now", "today"), False),
        (),
    ),
    "hltl.grounding._rewrites51:_will51": ("9ac9239bc464acd0", ((), ("will ",), False), ()),
    "hltl.grounding._rewrites51:_would_have51": (
        "e568ae63977b3ebb",
        ((), (" have ", " of ", "'ve "), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_and_then_who51r": (
        "95f4f5d14c14f3d6",
        ((), ("actually",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_done_after51r": (
        "b7f5d951ece1ed50",
        (
            (),
            (
                "brought",
                "drunk",
                "eaten",
                "finished",
                "gave",
                "given",
                "got",
                "had",
                "handed",
                "passed",
                "sent",
                "taken",
                "took",
                "used",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites51r:_excluded_back51r": (
        "f9e2d838d87bedd9",
        (
            (),
            ("apart", "bar ", "besides", "but not", "except", "excluding", "other than", "save"),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites51r:_instead_twice51r": (
        "404ec027fdebaa37",
        ((), ("instead",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_not_said51r": ("d9a0f7aa1f2c4179", ((), ("not ",), False), ()),
    "hltl.grounding._rewrites51r:_owner_said51r": ("9d0f456e95a8343c", (("'s",), (), False), ()),
    "hltl.grounding._rewrites51r:_people_had51r": ("cabf84b5e68f2846", ((), (" or ",), False), ()),
    "hltl.grounding._rewrites51r:_well_again51r": ("6bc8b553a713e7df", ((), ("well",), False), ()),
    "hltl.grounding._rewrites51r:_who_wants51r": ("313b3da0d03e554c", ((), (" or ",), False), ()),
    "hltl.grounding._rewrites51s:_later_texted51s": (
        "6a65d9e17a1bd913",
        ((), ("2m", "2n", "l8", "tm", "tomoz", "tonite"), False),
        (),
    ),
    "hltl.grounding._rewrites52:_had_wanted52": (
        "88170edaf40d47fa",
        ((" had ", "'d "), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_should52": ("64b9ba5f804a9c7b", (("?",), (), False), ()),
    "hltl.grounding._rewrites52r:_done_it52r": (
        "1d0c1cc33cf3495a",
        ((), ("dealt", "done", "seen to", "sorted"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_never_noted52r": (
        "530e2850c9dccb95",
        ((), ("which",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_one_of_the_girls52r": (
        "9df382d98be62a2d",
        ((), ("one of the",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_one_who52r": (
        "814d5f8343ef8f7f",
        ((), ("the one",), False),
        (
            (
                "_BACK51R",
                (
                    "pattern",
                    "\\b(?:no|sorry|wait|hang on|hold on|scratch that|strike that|my mistake|my bad|whoops|oops|actually|i mean|i meant)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites52r:_or_was_it52r": (
        "04f1a7f95cf24d21",
        ((), ("or is it", "or was it"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_too_after52r": (
        "d81fe6eadf5bac6c",
        ((), (" also", " too", "as well"), False),
        (),
    ),
    "hltl.grounding._rewrites52s:_having_done52s": (
        "a92c14b86eda292f",
        ((), ("having",), False),
        (),
    ),
    "hltl.grounding._rewrites52s:_she_wants_other52s": (
        "4db9050473262b92",
        ((), ("he",), False),
        (),
    ),
    "hltl.grounding._rewrites53:_does_he53": ("5266ca056de313c1", (("?",), (), False), ()),
    "hltl.grounding._rewrites53:_forgot_which53": ("0a25e216e99e1afb", (("?",), (), False), ()),
    "hltl.grounding._rewrites53l:_held_request53l": (
        "c39ac8694347e3bc",
        (("got", "had", "has"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_each_head53r": ("35b543b95513fc71", ((), (":",), False), ()),
    "hltl.grounding._rewrites53r:_lost_who53r": ("301d7d838067f794", ((), (" who",), False), ()),
    "hltl.grounding._rewrites53r:_one_of_two53r": (
        "a2e5e42f2528dc03",
        ((), ("one of th",), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_everything_said53s": (
        "918d412996c10614",
        ((), ("all of", "every", "the lot"), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_not_them53s": (
        "116038908559c8fe",
        ((), ("instead of", "not ", "rather than"), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_pronoun_had53s": (
        "7aadc25bb222f6b0",
        ((), (" got ", " had "), False),
        (),
    ),
    "hltl.grounding._rewrites54:_could_have54": ("5b4a53610fbbc758", ((), ("?",), False), ()),
    "hltl.grounding._rewrites54:_did_you54": (
        "a2e8784c640e9bfb",
        ((), ("did you", "had you", "have you"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_had_asked54": (
        "67fbb5d3305c7c7a",
        ((), (" had ", "'d "), False),
        (),
    ),
    "hltl.grounding._rewrites54:_had_why54": (
        "d306486a0141109a",
        ((), ("got ", "had "), False),
        (),
    ),
    "hltl.grounding._rewrites54l:_had_given54l": ("e71907cea550ea54", (("had",), (), False), ()),
    "hltl.grounding._rewrites54l:_held_and_more54l": (
        "195f862eda749571",
        (("got", "has"), (), False),
        (),
    ),
    "hltl.grounding._rewrites54l:_held_corrected54l": (
        "3e9480485bdca49f",
        (("got", "has"), (), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_both_things54r": ("eeff56a3abbe8a49", ((), ("both",), False), ()),
    "hltl.grounding._rewrites54s:_own_to_other54s": ("cc2b3bf2ebacd293", (("'s ",), (), False), ()),
}
