# ruff: noqa: E501
"""The normaliser's step guards (made by python -m hltl.grounding.stepguard --write)."""

from hltl.grounding.stepguard import Entry

GUARDS: dict[str, Entry | str] = {
    "derivation": "33d71a3257a14c08229c5a2993d046f6",
    "hltl.grounding._normalise1:_a_kind_for": (
        "23e50baa0c8ff88e",
        ((), ("for", "to"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_after": (
        "8d32d28388a12398",
        ((), ("after ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_after_those": (
        "71e6db83a7cf4867",
        ((), ("after th",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_all_counted": (
        "5cc20fda53ea1f4a",
        ((), (" taking ", "all "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_answered": (
        "cdf84d04e312708b",
        ((), ("which ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_asked_then_told": (
        "a97fcbcc437b4d49",
        ((), ("how long", "is there", "won't you"), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_better": (
        "3972387756ce6375",
        ((), ("best", "better", "nicer", "safer"), True),
        (
            (
                "_BETTER",
                (
                    "value",
                    "\"(?:'s|\\\\s+is|\\\\s+would be|\\\\s+'d be|\\\\s+will be|\\\\s+might be|\\\\s+may be|\\\\s+seems|\\\\s+looks|\\\\s+sounds)(?: even| much| a lot| probably| definitely)? (?:better|best|nicer|safer|a better (?:place|spot|bet|idea|choice|option)|the better (?:place|spot|bet|choice|option))\\\\b\"",
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_both_got_theirs": (
        "097754a92730c4b7",
        ((), (" theirs",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_both_of31s": (
        "95e6c13f5c44b5ba",
        ((), (" of th", "all three", "both"), True),
        (
            (
                "_BOTH_OF31S",
                (
                    "pattern",
                    "(?:^|(?<=[.!?] ))(?:(?P<both>both|the two|all three|the three) of (?:them|those|these)(?P<list>,\\s*[^,.;!?]+?,)?|(?P<alone>both|all three),\\s*(?P<listed>[^,.;!?]+?),)(?= (?:to|for|on|onto|in|into|go|goes|over|up|across)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise1:_both_them17": (
        "a43a0bee24a06018",
        ((), (" and the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_can_wait": (
        "f4261757cbca8011",
        ((), (" can wait",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_chance": (
        "263234e68df7b76d",
        ((), ("any ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_choice": (
        "d8e7264cb9c5845b",
        (
            (),
            (
                " and one ",
                "a couple of ",
                "any ",
                "both ",
                "choose",
                "fancies",
                "fancy",
                "item",
                "like",
                "object",
                "pick",
                "prefer",
                "the only ",
                "thing",
                "want",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_choices17": (
        "522e4e2c31f4f0f1",
        ((), ("either ", "one of the ", "whichever ", "whoever"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_confirmed": (
        "88d94c4db2184ce6",
        ((), ("eah", "ep", "es", "i mean", "up"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_correction_frames": (
        "2e57a693c026edbd",
        (
            (),
            (" wanted?", "correction", "my mistake", "no,", "not ", "silly me", "the ", "wait"),
            True,
        ),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_corrections17": (
        "2ff2c2c1cae6856c",
        ((), (" not ", " to ", "actually", "i meant", "swap the "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_corrections18": (
        "d546bab66801d9ae",
        (
            (),
            (
                "correction",
                "gets",
                "i mean the ",
                "leave ",
                "make that",
                "needs",
                "sorry,",
                "wait,",
                "wants",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_counted_list": (
        "a2205ab2db9353fa",
        ((), ("each of ", "for", "in", "on", "to"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_counts17": (
        "2977bae890caebfb",
        (
            (),
            (" there is", "a couple of things", "every one of the ", "the one", "the pair of "),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_counts18": (
        "81f2dc6c9c77eac9",
        (
            (),
            (
                " and ",
                " of the ",
                " trio of ",
                "'s for the ",
                "for each ",
                "pair of ",
                "per ",
                "the two of them,",
                "there's ",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_courtesy": (
        "1cb31770bd6ff746",
        (
            (),
            (
                " be ",
                " but ",
                " forget to ",
                " thanks",
                " to get ",
                ",",
                "a gem",
                "a lifesaver",
                "a star",
                "afternoon",
                "ah",
                "an angel",
                "and that's ",
                "appreciate it",
                "as far as i know",
                "ask",
                "asking for",
                "at some ",
                "be ",
                "beg",
                "bless ",
                "both ",
                "by the way",
                "come on",
                "discussed",
                "evening",
                "excuse",
                "for ",
                "for the record",
                "for us",
                "for your information",
                "get",
                "good",
                "good ",
                "has not",
                "hasn't",
                "have",
                "heads up",
                "hello",
                "hey",
                "hi",
                "hoping",
                "hurry",
                "i am ",
                "i believe",
                "i guess",
                "i imagine",
                "i reckon",
                "i said",
                "i suppose",
                "i think",
                "i would say",
                "i'd say",
                "i'm ",
                "if i remember ",
                "if you",
                "if you ",
                "is it",
                "it is",
                "it's",
                "just so y",
                "kind",
                "kindly",
                "listen",
                "lovely",
                "make sure ",
                "make sure not to",
                "mentioned",
                "morning",
                "much",
                "much appreciated",
                "much obliged",
                "nice",
                "oh",
                "ok",
                "over and out",
                "pardon",
                "poor ",
                "request",
                "requesting",
                "right",
                "rush",
                "so",
                "so ",
                "sweet",
                "thanks ",
                "that is",
                "that would be",
                "that'd be",
                "that's",
                "that's it",
                "the best",
                "to ",
                "when",
                "where ",
                "whoever ",
                "will it be",
                "would it be",
                "yep",
                "yes",
                "you know",
                "you see",
            ),
            True,
        ),
        (
            (
                "_ASKED",
                (
                    "patterns",
                    "pairs",
                    (
                        "(^|(?<=[.;!?])\\s*)(?:i|we)(?:'d| would)? (?:request|ask|beg) (?:you |that you )?(?:to )?(?=(?:give|hand|pass|bring|take|put|place|move|fetch|send|get)\\b)",
                        "\\s*(?:\\bis|'s|\\bare|'re) (?:requesting|asking for)\\b",
                        "\\b(?:needs?|has|have) to get (?:over )?to\\b",
                        "^((?:the )?[\\w ]+?) (?:still )?(?:hasn't|has not|hasn't yet|has not yet|still hasn't) (?:had|got|gotten|received) (?![^.!]*\\b(?:or|nor|and|any|either|neither|all|both)\\b)((?:his|her|their|the|a|an) [\\w ]+?)(?: yet)?\\s*[.!]?$",
                        "(\\bor\\b[^.;!?]*?),\\s*whoever (?:wants|needs|likes|would like|prefers) (?:it|them|one)\\b",
                        "(^|(?<=[.;!?])\\s*)(?:is it|would it be|will it be) (?:at all )?(?:possible|ok|okay|alright|all right|fine) (?:for|if) ((?:the )?[\\w ]+?) (?:to have|to get|had|got|could have|could get|has|gets) ",
                        "\\bboth (need|want|would like|get|should get|could use)s? (a|an|one) ([a-z]+(?: [a-z]+)?)(?=\\s*(?:[.,;!?]|$|please))(?!,?\\s*so one each)",
                    ),
                ),
            ),
            (
                "_COURTESY",
                (
                    "patterns",
                    "pairs",
                    (
                        "(^|(?<=[.;!?])\\s*)(?:there'?s )?no (?:rush|hurry)(?: at all)?(?:\\s*[,.!;]\\s*|\\s+)(?:but\\s+)?",
                        "^(?:(?:hi|hello|hey|hiya|yes|yeah|yep|ok|okay|right|morning|evening|afternoon|good (?:morning|afternoon|evening|day)|ah|oh)(?: there)?\\s*[,!]\\s*|(?:(?:(?:excuse|pardon) me(?:,? (?:so )?sorry)?|(?:so )?sorry,? (?:excuse|pardon) me)(?:,? (?:(?:so )?sorry )?(?:to|for) (?:bother|interrupt|trouble|disturb|rush)(?:ing)?(?: you)?)?|(?:so )?sorry (?:to|for) (?:bother|interrupt|trouble|disturb|rush)(?:ing)?(?: you)?|listen(?: up)?|look|come on(?: then| now)?|lovely|so)\\s*[,.!]\\s*(?=[a-z]))+",
                        ",?\\s*\\bat some (?:point|stage)(?: today| later)?\\b",
                        "(^|(?<=[.;!?])\\s*)(?:whenever|when) (?:you'?re|you are) (?:ready|free)\\s*[,.]?\\s*",
                        "(^|(?<=[.;!?,])\\s*)(?:(?:could|would|can|will) you |so |and |please |now )*be (?:an? )?(?:angel|dear|star|love|darling|gem|sweetheart|sweetie|pal|treasure|doll|lamb|good (?:robot|lad|girl|boy))(?:\\s+and\\b|\\s*[,:])\\s*",
                        "\\b(?:(?:would|could|will) you )?(?:please )?be (?:ever |so |very )*(?:so )?(?:kind|good|nice|sweet)(?: as to| and| enough to)\\b,?\\s*",
                        ",?\\s*\\bif you(?:'d| would| could)? (?:be )?(?:ever )?so (?:kind|good)\\b\\s*,?",
                        ",?\\s*\\bif you (?:wouldn't|would not|don't|do not|didn't|did not) mind\\b\\s*,?",
                        "\\b(?:thank you|thanks|ta|thx)(?:\\s+(?:ever|so|very|really|most|kindly))*\\s+(?:much|kindly)\\b",
                        "\\bthanks (?:a (?:million|bunch|lot|ton|heap)|loads|heaps|again|in advance)\\b",
                        "\\b(?:many|big|huge) thanks\\b",
                        ",?\\s*\\b(?:much appreciated|(?:i |really )*appreciate it|you'?re (?:a star|an angel|a gem|a lifesaver|the best))\\b",
                        "(^|(?<=[.;!?])\\s*)(?:just so (?:you know|ya know)|heads up|by the way|for the record|for your information|as (?:i said|mentioned|discussed)|like i said)\\s*[,:!-]?\\s*",
                        ",\\s*(?:bless (?:him|her|them|'?em)|(?:the )?poor (?:thing|dear|love|lamb|soul|mite|guy|man|woman|kid|pet|sausage)s?)(?=\\s*(?:[.,;!?]|$))",
                        ",?\\s*\\b(?:that |it )?(?:would|'d|will) be (?:great|lovely|brilliant|perfect|wonderful|amazing|fab|fantastic|ideal|helpful|super|awesome|appreciated|much appreciated)\\b",
                        ",?\\s*\\bif (?:that's|that is|it's|it is|that'd be|that would be) (?:ok|okay|alright|all right|fine)(?: with you| by you)?\\b",
                        "(^|(?<=[.;!?])\\s*)much obliged\\b[.!]*",
                        "\\b(?:could|can|may|might) (?:i|we) (?:get|ask|have) (?:you|the robots?|the arms?|it) (?:to )?(?=(?:give|hand|pass|bring|take|put|place|move|fetch|send)\\b)",
                        ",?\\s+where (?:it|they) (?:belongs?|lives?|goes|go|should be)\\b",
                        "\\s+for (?:later|now|a (?:sec|second|minute|moment|bit|while)|the (?:moment|time being|day|night|week|weekend)|tonight|tomorrow|today)\\b(?=\\s*(?:[.,;!?]|$|please|thanks))",
                        ",\\s*(?:you know|you see|over and out|and that's (?:it|that)|that's it)(?=\\s*(?:[.!?]|$))",
                        ",?\\s*\\b(?:whenever|when) (?:you're|you are) (?:ready|free|able)\\b",
                        "(^|(?<=[.;!?])\\s*)(?:i'd say|i would say|if i'm not mistaken|if i remember (?:right|rightly|correctly)|as far as i know|i suppose|i imagine|i'm (?:pretty |fairly )?sure|i am (?:pretty |fairly )?sure|i think|i believe|i reckon|i guess)(?: that)?\\s*,?\\s*",
                        ",?\\s+so (?:that )?(?:he|she|they|it) (?:can|could|has|have|will|'ll|won't|doesn't|don't|isn't|is|are|gets?) [a-z' ]{2,40}?(?=\\s*(?:[.;!?]|,\\s*(?:please|thanks)\\b|$))",
                        "(?<!thing)(?<!stuff)\\s+(?:so as )?to (?:soak|dry|cool|cool down|warm up|eat|drink|use|read|charge|share|keep|wash|clean|play with|play|sign|fix|cut|write|write with|work|work with|snack on|look at|finish|study|sort|pack|label|scan)\\b(?: [a-z]+){0,3}?(?=\\s*(?:[.;!?]|,\\s*(?:please|thanks)\\b|$|\\s+please\\b))",
                        ",\\s*(?:um+|uh+|erm*|er|hmm+|ah+)\\s*,",
                        "(^|(?<=[.;!?])\\s*)(?:i was|i'm|i am|we were|we're|we are) (?:just |really )?hoping(?: that)? ",
                        "(^|(?<=[.;!?,])\\s*)(?:please )?(?:don't|do not) forget to ",
                        "\\bmake sure (?:that )?(?:you )?(don't|do not|never)\\b",
                        "\\bmake sure not to\\b",
                    ),
                ),
            ),
            ("_drop", ("function", "hltl.grounding._normalise1:_drop", "8cf37521cc8fd8a7")),
            (
                "_for_us",
                (
                    "guarded",
                    "hltl.grounding._normalise1:_for_us",
                    "bb030929c6c9cb58",
                    (
                        (
                            "_FOR_US",
                            ("value", "'\\\\s+for us\\\\b(?=\\\\s*(?:[,.;!?]|please|thanks|$))'"),
                        ),
                        (
                            "_sub",
                            ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77"),
                        ),
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_courtesy14": (
        "76dd7e6f587e1966",
        (
            (),
            (
                " be ",
                " not too much to ask",
                ",",
                "appreciate ",
                "bless y",
                "bother",
                "fuss",
                "god bless",
                "hassle",
                "imposition",
                "inconvenience",
                "isten",
                "it is",
                "it's",
                "ook",
                "pain",
                "problem",
                "sorry ",
                "there is one",
                "there's a ",
                "there's one",
                "they are",
                "they're",
                "trouble",
                "ur",
                "what",
                "you are",
                "you really are",
                "you're",
            ),
            True,
        ),
        (
            (
                "_COURTESY14",
                (
                    "patterns",
                    "pairs",
                    (
                        "(^|(?<=[.;!?,])\\s*|\\s+)if (?:it's|it is|that's|that is|it isn't|it is not|it wouldn't be|it would not be|it's not|that's not|that isn't) (?:not )?(?:too much |much |a |any |no |of )*(?:bother|trouble|problem|hassle|inconvenience|imposition|fuss|pain)(?: for you| to you| at all)?\\b\\s*[,.]?\\s*",
                        "(^|(?<=[.;!?,])\\s*|\\s+)if (?:it's|it is) not too much to ask\\b\\s*[,.]?\\s*",
                        ",?\\s+if (?:it's|it is|they're|they are|there's one|there is one) (?:still )?(?:going|free|spare|available|about|around|handy|to hand|not (?:being )?used|not in use)\\b",
                        "(^|(?<=[.;!?])\\s*)(?:(?:hi|hello|hey|oh),?\\s+)?(?:(?:i'm|i am) )?(?:so |really |very |terribly |awfully |ever so |truly )*sorry (?:to (?:bother|interrupt|trouble|disturb|pester|hassle|ask|nag|be (?:a |such a )?(?:pain|nuisance|bother|pest))(?: you)?(?: again)?(?: all)?|for (?:the )?(?:bother|interrupting|interruption|bothering you|troubling you|asking))\\b\\s*(?:[,.!]+\\s*(?:but\\b)?|\\s+but\\b)?\\s*",
                        ",\\s*there's a (?:good |clever |lovely |smashing )?(?:robot|lad|girl|boy|chap|fella|one)(?=\\s*(?:[.!]|$))",
                        ",?\\s*\\b(?:that|it|this)(?:\\s+would|'d|\\s+will|'ll) be (?:just |really |so |absolutely |a )?(?:grand|ace|magic|class|champion|smashing|sound|deadly|cracking|tops|terrific|tremendous|marvellous|marvelous|splendid|sweet|nice|good|cool|fab|fabulous|excellent|superb|stellar|kind|very kind|so kind|(?:a |such a )?(?:great |big |huge |real )?(?:help|lifesaver|godsend))\\b",
                        ",?\\s*\\b(?:god )?bless (?:you|ya|ye|your (?:heart|cotton socks))\\b",
                        "(^|(?<=[.;!?])\\s*)god bless\\b[.!]*",
                        "(^|(?<=[.;!?])\\s*|,\\s*)(?:i |really )*appreciate (?:you|ya|ye|it|that)\\b[.!]*",
                        "(^|(?<=[.;!?])\\s*)(?:(?:ok|okay|right|so|now|alright|hey|oh)[,]?\\s+)*(?:listen|look)(?: up| here| now)?(?:\\s*[,:!.-]+\\s*|\\s+(?=(?:the|a|an|could|can|would|will|please|give|hand|pass|bring|put|take|pop|grab|fetch|ok|so|just)\\b))",
                    ),
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_PRAISE",
                (
                    "patterns",
                    "strings",
                    (
                        "(^|(?<=[.;!?])\\s*)(?:(?:oh|aw|ah|ooh),?\\s+)?(?:you're|you are|ur|you really are|what) (?:such |an? |the |my |absolute |total |real |proper |complete |little |true |utter )*[a-z-]+(?:\\s+[a-z-]+)?\\s*[,.!]+\\s*",
                        "(),\\s*(?:you're|you are|ur|you really are|what) (?:such |an? |the |my |absolute |total |real |proper |complete |little |true |utter )*[a-z-]+(?:\\s+[a-z-]+)?(?=\\s*(?:[.!]|$))",
                    ),
                ),
            ),
            ("_drop", ("function", "hltl.grounding._normalise1:_drop", "8cf37521cc8fd8a7")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_courtesy17": (
        "2d31544ad88924f7",
        (
            (),
            (
                " and ",
                "cheers",
                "could i ",
                "now then",
                "oh dear",
                "sorry to ",
                "ta",
                "thank you",
                "thanks",
                "there's a",
                "won't you",
            ),
            True,
        ),
        (
            (
                "_ENDEARING",
                (
                    "value",
                    "'(?:love|dear|darling|pet|sweetheart|star|good (?:robot|lad|girl|boy|helper))'",
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_courtesy_frames": (
        "2207683a52f6d798",
        (
            (),
            (
                " you be ",
                "be a",
                "cheers",
                "convenience",
                "convenient",
                "go",
                "i hope ",
                "i know ",
                "if that's ",
                "if you don't mind",
                "next ",
                "one ",
                "order",
                "pretty please",
                "ready",
                "table",
                "thank you",
                "thanks",
                "ticket",
                "up",
                "when you get a ",
                "yes",
                "you can",
            ),
            True,
        ),
        (
            (
                "_COURTESY_FRAMES",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\b(would|could|will|can) you be (?:a|an|my) (?:(?:good|real|proper|absolute|kind|lovely|little|total) )?[a-z]+ and\\s+",
                        "^(?:be (?:a|an) [a-z]+ and|be a love,?)\\s+",
                        "\\bpretty please(?: with (?:sugar|a cherry|cherries|bells) on(?: top)?)?\\b",
                        "(^|(?<=[.!?])\\s*)(?:when (?:convenient|it's convenient|you can)|at your (?:earliest )?convenience|when you get a (?:chance|minute|moment|sec|second|tick))\\s*,\\s*",
                        "(^|(?<=[.!?,])\\s*)(?:um,?\\s*|er,?\\s*)?i hope (?:this|that|it)(?:'s| is) (?:okay|ok|alright|all right|fine)\\s*,\\s*",
                        "(^|(?<=[.!?,])\\s*)(?:oh,?\\s*)?(?:thank you|thanks|cheers)(?: so much| very much| again)? for (?:earlier|before|this morning|yesterday|last time)\\s*[,.!]\\s*(?:you(?:'re| are| were) (?:very |so |really )?[a-z]+\\s*[.!,]\\s*)?(?:now,?\\s*)?",
                        "(^|(?<=[.!?])\\s*)(?:and |just )?one (?:more|last) (?:favour|favor|thing|job)(?: for me)?\\s*[,:]\\s*",
                        ",?\\s*if that's (?:alright|all right|okay|ok|fine)(?: with (?:you|you all|everyone|everybody|all of you))?(?=\\s*(?:[.!:]|$))",
                        ",?\\s*if you don't mind\\s*(?=[,:])",
                        "(^|(?<=[.!?])\\s*)(?:sorry,?\\s*)?i know (?:it's|it is|you're|you are|things are|we're) (?:a bit |very |so |really )?[a-z]+(?: (?:in here|out there|today|right now|at the moment|this morning|tonight))?\\s*,?\\s*(?:but|so)\\s+",
                        "^(?:next|new|another) (?:order|ticket|table)\\s*[.!:]\\s*",
                        ",?\\s*(?:go,?\\s*){2,}go[.!]*$|,?\\s*go go[.!]*$",
                    ),
                ),
            ),
            ("_drop", ("function", "hltl.grounding._normalise1:_drop", "8cf37521cc8fd8a7")),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_courtesy_ifs": (
        "53e3ae9e16d5d7b1",
        ((), ("hand-over", "handover", "if ", "needful", "notes", "while "), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_described": (
        "984981f00c4673b9",
        ((), ("that one", "the "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_dictated": (
        "eaf6756aa73992c9",
        ((), ("done",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_either_fine": (
        "1d964c8933bf8256",
        ((), ("either ", "either's "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_either_of": (
        "d5cfd01aa9bad2b8",
        ((), ("each of the ", "either of ", "whoever"), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_either_one": (
        "5f3c16e306e8a5ba",
        ((), (" or ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_ends_up_with55p": (
        "06ce4e01c9055fe1",
        ((), (" up with",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_excluded_count": (
        "a21f118b055b1f28",
        ((), ("apart from", "aside from", "besides", "except", "other than"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_exclusion_frames": (
        "9507f701bf9e57a3",
        (
            (),
            (
                " for ",
                " is the one ",
                " the rest",
                "everything",
                "just ",
                "nothing else",
                "the lot",
            ),
            True,
        ),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_exclusions17": (
        "22eaf198ca6f6931",
        ((), (" having", " only ", "besides", "but not ", "leave ", "whichever "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_for_theirs55l": (
        "8e222a00c0af99cb",
        (("For ", "for "), (), False),
        (),
    ),
    "hltl.grounding._normalise1:_fronted": (
        "cc07857c948bc8bb",
        ((), ("apart from", "except", "not", "other than"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_given_nothing": (
        "d561dbb06b7d5f13",
        ((), ("nothing",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_handy": (
        "bbdca50a14360cc0",
        ((), ("atever", "ichever"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_HANDY",
                (
                    "value",
                    "'nearer|closer|nearest|closest|handiest|handier|easiest|easier|quickest|quicker|easiest to reach|easier to reach|nearest to hand|closest to hand|within reach|to hand'",
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_i_mean_it": (
        "962263c8af5c9054",
        ((), ("i mean",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_just_one": (
        "33bdd96d8943f1e4",
        ((), ("one ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_labels": (
        "352f5e6c8d658f19",
        (("-", ":"), (), True),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise1:_lacks": (
        "e0d69f3095841bcb",
        (
            (),
            (
                "'s out of",
                "'s run out of",
                "can not find",
                "can't find",
                "cannot find",
                "does not have",
                "doesn't have",
                "forgot",
                "has no",
                "has run out of",
                "hasn't",
                "is out of",
                "lost",
                "ran out of",
            ),
            True,
        ),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_leave_it": (
        "c17f33b6a0afc333",
        ((), ("forget ", "leave it", "leave that", "never mind", "scrap that"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_left_with55p": (
        "d58a9098ab25f2ae",
        ((), ("with",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_likewise": (
        "bf38b156b02ba78a",
        ((), ("likewise", "same again", "same thing", "the same"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_listed": (
        "1623db2210e1ca93",
        ((), (" of th", "all", "both", "these", "those"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_my_mistake": (
        "fd7c5cd9ba339965",
        (
            (),
            (
                "it goes",
                "it is",
                "it should be",
                "it should go",
                "it's",
                "that should be",
                "that's",
                "they are",
                "they're",
            ),
            True,
        ),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_negated": (
        "371e87bcd0592155",
        ((), ("do not", "don't", "dont", "never", "not "), True),
        (
            (
                "_DONT",
                (
                    "value",
                    '"(?:please |just |and |but |so |also )*(?:don\'t|do not|dont|never)\\\\s+"',
                ),
            ),
            (
                "_DO_VERBS",
                (
                    "value",
                    "'(?:give|hand|pass|bring|take|send|put|place|move|leave|set|drop|deliver)\\\\b'",
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_negation18": (
        "83f8ffce29a6a55d",
        ((), (" for ", " that ", "bar the", "don't give ", "just the "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_not_first": (
        "bae04469d9c2a480",
        ((), ("leave the ", "not "), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_one_each": (
        "b42daabfc20c6777",
        ((), ("one each",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_order_again": (
        "79f34042827fcd16",
        ((), ("first",), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_possessed14": (
        "9c3faf5edcd9f7fb",
        ((), (" yours", "'s request", "th"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_purpose": (
        "00bdb76d1296a08f",
        ((), ("for ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_questions17": (
        "47c31f95f21e6e1c",
        (
            (),
            (
                " along to",
                " can ",
                " over to ",
                "any chance of ",
                "charging",
                "cleaning",
                "drying",
                "washing",
                "you can ",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_rather": (
        "093d2dc226cdc820",
        ((), ("instead of", "rather than"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_reasons21": (
        "ff84c2ad390b30a4",
        (
            (),
            (
                " are",
                " can",
                " had",
                " has",
                " have",
                " is",
                " just",
                " keep",
                " was",
                " were",
                " will",
                "'d",
                "'ll",
                "'m",
                "'re",
                "'s",
                "'ve",
                "her",
                "his",
                "its ",
                "my",
                "our",
                "table ",
                "the",
            ),
            True,
        ),
        (
            (
                "_REASON21",
                (
                    "pattern",
                    "(?:\\s*[,;]\\s*|\\s+[—–-]\\s+|\\s+(?=its [a-z]+ing\\b))((?:(?:oh|and|cos|coz|cause|because|as|since)\\s+)?(?:(?:she|he|it|they|we|i)(?:'s|'re|'ve|'ll|'d|'m| is| are| was| were| has| have| had| keeps?| will| can| just)|its [a-z]+ing|(?:her|his|their|my|our|the) [a-z]+(?:'s| is| are| was| were| has| keeps?)|table (?:one|two|three|four|five|six|seven|eight|nine|ten|\\d+)(?:'s| is| are))\\b[^,.;!?—–]*?)\\s*(?=[.!?]|$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise1:_redone": (
        "dfa49fac4d55bf44",
        ((), ("leave the", "not the"), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_remark_owner": (
        "84f74e2ec57ef247",
        ((), (" is", " was", "'s"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_reordered": (
        "494210e07bafc543",
        ((), (" first",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_restated20": (
        "5d3a113a0278d853",
        (
            (),
            (" that wrong", "actually", "correction", "hang on", "hold on", "no", "sorry", "wait"),
            True,
        ),
        (
            (
                "_RESTATE20",
                (
                    "pattern",
                    "(?:(?<=[.!?])\\s+|\\s*,\\s*)(?:(?:oh,? )?(?:no|sorry|correction|hang on|hold on|wait)(?:,? (?:actually|sorry|no|wait|(?:my )?mistake))?(?:,? i said that wrong| i got that wrong| that's wrong)?|sorry,? i (?:said|got) that wrong|actually,? no)\\s*[,.:;!]\\s*(?:actually\\s*,\\s*)?",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise1:_run_on": (
        "c30b4436fd7719ab",
        ((), ("he",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_run_on_leads": (
        "67a1ff727c67be36",
        ((), (" so ", "listen up"), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_run_on_remarks": (
        "c10566d7e79e5ea9",
        ((), (" the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_said14": (
        "ee951b41b5b4a07d",
        (
            (),
            (
                " to ",
                " you to do",
                "about now",
                "ahoy",
                "alexa",
                "all of it",
                "any old",
                "as i mentioned",
                "as i said",
                "asking",
                "assistant",
                "aye",
                "bay",
                "bed",
                "biggie",
                "bless ",
                "bob's your uncle",
                "bother",
                "chair",
                "computer",
                "cooee",
                "cortana",
                "cubicle",
                "day",
                "desk",
                "dramas",
                "eh",
                "eh up",
                "evening all",
                "everything",
                "ey up",
                "favo",
                "google",
                "got it?",
                "hello all",
                "hi all",
                "hiya",
                "howay",
                "howdy",
                "if i remember ",
                "innit",
                "job done",
                "job's a good 'un",
                "kindness",
                "let me ",
                "let me see",
                "let me think",
                "let's see",
                "like i said",
                "morning all",
                "now then",
                "oi",
                "ok?",
                "okay?",
                "please to",
                "possible ",
                "problem",
                "probs",
                "reckon",
                "requesting",
                "right then",
                "right?",
                "robot",
                "room",
                "row",
                "seat",
                "see ",
                "siri",
                "solid",
                "sorted",
                "station",
                "stress",
                "sup",
                "sweat",
                "table",
                "that's the lot",
                "that's your lot",
                "the ",
                "there we go",
                "there you are",
                "there you go",
                "understood?",
                "w line",
                "w paragraph",
                "ward",
                "watcha",
                "well then",
                "what did i want",
                "what else",
                "what was i saying",
                "what was it",
                "what's next",
                "when you",
                "where was i",
                "worries",
                "wotcha",
                "xt line",
                "yeah?",
                "yo",
                "you mind",
                "your ",
            ),
            True,
        ),
        (
            (
                "_SAID14",
                (
                    "patterns",
                    "pairs",
                    (
                        "(^|(?<=[.;!?,])\\s*)(?:(?:could|would|can|will) you |please )?do (?:me|us) a (?:(?:big|quick|small|huge) )?(?:favou?r|kindness|solid)(?:\\s+and\\b|\\s*[,:!.]|\\s+please\\b,?)\\s*",
                        ",?\\s*(?:\\band\\s+)?\\b(?:there you go|there we go|there you are|bob's your uncle|that's the lot|that's your lot|that's the lot of them|job done|job's a good 'un|sorted|innit|eh|right\\?|ok\\?|okay\\?|alright\\?|yeah\\?|got it\\?|understood\\?|if i remember (?:right|rightly|correctly)|(?:just )?like i said(?: before| earlier)?|as i said(?: before| earlier)?|as i mentioned)(?=\\s*(?:[.!]|$))",
                        "(^|(?<=[.;!?])\\s*)(?:(?:just )?like i said(?: before| earlier)?|as i said(?: before| earlier)?|as i mentioned(?: before| earlier)?)\\s*,\\s*",
                        ",?\\s+bless (?:him|her|them|'?em)(?:,? the (?:poor )?(?:thing|dear|love|lamb))?(?=\\s*(?:[.!]|$))",
                        "(^|(?<=[.;!?])\\s*)(?:the (?:plan|idea|task|job|thing)|your (?:job|task)|what (?:i|we) (?:need|want|'d like) you to do) (?:is|will be|for now is) (?:to |that you |just )?",
                        "^(?:(?:ok|okay|hey|hi)\\s+)?(?:alexa|google|siri|computer|robots?|cortana|assistant)\\s*[,!.:]\\s*",
                        "\\b(you mind) (?:awfully|terribly|very much|at all|too much)\\b",
                        "\\s*\\((?:in )?(?:bed|room|bay|seat|desk|table|station|row|cubicle|ward|chair) ?\\w{1,4}\\)",
                        ",\\s*(?:in )?(?:bed|room|bay|seat|station|row|cubicle|chair) (?:\\d{1,3}|one|two|three|four|five|six)\\s*,",
                        "(^|(?<=[.;!?])\\s*|,\\s*)(?:no (?:worries|dramas|problem|probs|bother|biggie|sweat|stress)(?: at all)?(?: mate| love)?)(?:\\s*[,.!]+\\s*|\\s*$)",
                        "^(?:g'?day|howay|ey up|eh up|hey up|wotcha|watcha|oi|cooee|yo|aye|ahoy|howdy|hiya|sup|wassup|now then|well then|right then|morning all|evening all|hello all|hi all)(?: (?:mate|love|pet|folks|guys|all|there|dear))?\\s*[,!.:]+\\s*",
                        "^(?:(?:now|so|right|ok|okay|um+|er+m?|hmm+),?\\s+)?(?:where was i|what was it|what else|what was i saying|what did i want|let me think|let me see|let's see|what's next|now then)\\s*[?.!,…]+\\s*(?:(?:oh|ah|ahh|yes|yeah|right|that's it|that's right)[,!.]*\\s+)*",
                        ",\\s*let me (?:think|see|check|look)(?: (?:at )?(?:my|the) (?:list|notes|sheet|order))?\\s*,\\s*(?=(?:no|sorry|actually)\\b)",
                        "^(?:i )?reckon,?\\s+",
                        "(^|(?<=[.;!?])\\s*)(?:i'm|i am|we're|we are) (?:kindly )?(?:asking|requesting) (?:you )?(?:to )?(?=[a-z])",
                        "^(?:is|would be|will be) (?:it )?possible (?:for you )?to (?=[a-z])",
                        "\\bplease to\\b",
                        "\\b(must|should|can|could) to (?=have|get|give|put|bring|take)\\b",
                        "(?:\\b(?:would|could|can|will) you )?(?:kindly |please )*\\bsee (?:to it )?(?:that )?(?=(?:the )?[a-z][\\w ]*? (?:gets?|receives?|has)\\b)",
                        "\\bthe (?:whole )?lot\\b(?! of\\b)",
                        "^all of it\\b",
                        "\\b(everything|everything else)\\s+bar\\s+(?=the\\b)",
                        "\\bany old\\b",
                        ",?\\s+when (?:you're|you are|you've|you have) (?:done|finished|free|ready|got a (?:sec|minute|moment|mo))\\s*([.!]?)\\s*$",
                        "\\s+(?:right )?about now\\b(?=\\s*(?:[.,;!?]|$))",
                        "(^|\\s+)(?:new line|next line|new paragraph)\\b\\s*",
                    ),
                ),
            ),
            ("_drop", ("function", "hltl.grounding._normalise1:_drop", "8cf37521cc8fd8a7")),
        ),
    ),
    "hltl.grounding._normalise1:_said_otherwise31s": (
        "fb24a3ef5c96a75a",
        (
            (),
            (
                " and ",
                " this morning",
                "after",
                "darling",
                "dear",
                "do likewise",
                "hun",
                "love",
                "mate",
                "pet",
            ),
            True,
        ),
        (
            (
                "_BOTH_AFTER31S",
                (
                    "pattern",
                    "\\b(?P<list>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?) both(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_said_why": (
        "d76b34f7f764fafa",
        ((), ("actually,", "no,", "sorry,"), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_same_but17": (
        "2c4f9347fc0cef97",
        ((), (" do the same for ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_same_person": (
        "df244e91f42d285b",
        ((), (" the same ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_see_it17": (
        "2ace60985f5b9a7a",
        ((), ("the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_sign_offs": (
        "ae36e8d421ae73dc",
        ((), ("before i", "before we", "from me", "from us", "that's me", "that's us"), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_sold18": (
        "4eaa702b9eb1e405",
        ((), ("sold to ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_speaker": (
        "5504b0a629bc50f5",
        ((), ("i am", "i'm", "im", "we are", "we're"), True),
        (
            (
                "_SELF",
                (
                    "pattern",
                    "(^|(?<=[.;!?])\\s*|(?<=,)\\s*)(?:(?:(?:hi|hello|hey|hiya)(?: there)?|sorry|excuse me|good (?:morning|afternoon|evening)|morning|evening)\\s*[,!.]?\\s*)*(?:i'm|i am|im|we're|we are)\\s+(?P<said>[^.;!?,]*?)(?:\\s*[.;!?]+\\s*|\\s*,\\s*(?:(?:so|but|and)\\b,?\\s*)?|\\s+(?:so|but)\\s+)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise1:_spoken": (
        "7563724a7ce1b567",
        (
            (),
            (" ye", "ll", "ou guys", "ou lot", "ou two", "ous", "ye", "you all", "you mind "),
            True,
        ),
        (
            (
                "_HEARERS",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\b(?:y'?all|ya'?ll|you-all|youse|yous|you guys|you lot|you two)\\b(?=\\s*(?:[,.!:;]|$|(?:mind|hand|pass|give|bring|put|take|pop|grab|get|fetch|be|please|could|can|would|will|need|have|should|must|go|just)\\b))",
                        "\\bye\\b(?=\\s+(?:mind|hand|pass|give|bring|put|take|pop|grab|get|fetch|be|please)\\b)",
                        "\\b(could|would|can|will|do|did|have|are|were) ye\\b",
                        "\\byou all\\b(?=\\s*(?:[,.!:;]|$|(?:mind|hand|pass|give|bring|put|take|pop|grab|get|fetch|please|could|can|would|will|need|have|should|must|just)\\b))",
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_take_backs": (
        "5662ebfb559c2e70",
        (
            (),
            (
                "let me",
                "no,",
                "or was it",
                "or, no",
                "scratch that",
                "tell a lie",
                "that's",
                "what am i",
            ),
            False,
        ),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_texting": (
        "53db44fce815c2a3",
        ((" ",), (), True),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise1:_thanks": (
        "6b97af1de22381ab",
        ((), ("cheers", "ta", "thank you", "thanks", "thx"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_them_one": (
        "a045246fb100cab7",
        ((), ("they",), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise1:_them_over": (
        "86e285a5539143e7",
        ((), (" over",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_there": (
        "65d75e346e486ead",
        ((), (" there",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_they_one": (
        "c0ab31df43920778",
        ((), (" they",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_topic": (
        "4f506cc8022ee90a",
        ((), (",",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_vocative": (
        "78b4a36efed96ece",
        ((",",), (), True),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise1:_want_frames": (
        "a81556b71dce33ab",
        (
            (),
            (
                "'d like",
                "about to",
                "fine with",
                "going to",
                "gonna",
                "happy with",
                "need",
                "want",
                "would like",
            ),
            True,
        ),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_wanted_for": (
        "53820db2fb19cfb4",
        ((), ("after", "need", "said", "says", "want", "would like"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise1:_wanted_placed": (
        "f6d9722cb685de93",
        (
            (),
            (
                "'d like",
                "'d love",
                "asked for",
                "could use",
                "needs",
                "wants",
                "would like",
                "would love",
            ),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_PLACED",
                (
                    "value",
                    "'put|placed|loaded|moved|set|stacked|popped|dropped|stored|stood|laid|kept|parked|shifted|carried|taken|brought'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_wanting_that": (
        "6701bb4b2ea8769f",
        ((), ("you ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise1:_wants": (
        "f7da6905f84059ef",
        (
            (),
            (
                " ask is for",
                " asking",
                "'d like",
                "asked for",
                "could use",
                "crying out",
                "desperate",
                "dying",
                "for ",
                "gagging",
                "gasping",
                "ike",
                "is after",
                "itching",
                "keen",
                "longing",
                "needs",
                "ove",
                "wants",
                "would like",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_wants14_56p": (
        "1ad7daf79c6e37ae",
        (
            (),
            (
                " be needing",
                " be wanting",
                " for ",
                " like",
                "do with",
                "needs",
                "order",
                "ordered",
                "request",
                "requested",
                "wants",
                "wants the the",
                "wondering ",
            ),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_WANTS14",
                (
                    "patterns",
                    "pairs",
                    (
                        "^((?:the )?[\\w ]+?) (?:was|is|'s|were|are|has been) (?:just )?wondering (?:if|whether) (?:he|she|they) (?:could|might|can|may) (?:have|get|borrow)\\b",
                        "\\b(?:could|can) (?:really |certainly |definitely |probably |just )?do with\\b",
                        "(?:\\s+(?:will|would)|'ll|'d) be wanting\\b",
                        "(?:\\s+(?:will|would)|'ll|'d) be needing\\b",
                        "^(?:(?:can|could|may) (?:i|we) (?:get|have|grab|please have|please get)|(?:i|we)'ll have|(?:i|we)'d like|(?:i|we) would like)((?: the| a| an| some) [\\w ]+?) for ((?:the )?[\\w ]+?)(\\s*,?\\s*please)?\\s*([.!?]?)$",
                        "^((?:the )?[\\w ]+?) (?:mentioned|was saying|has said|has mentioned|says|told (?:me|us)|let (?:me|us) know|was telling (?:me|us)|reckons|thinks)(?: that)? (he|she|they)(?:'d| would) like\\b",
                        "^((?:the )?[\\w ]+?) (?:mentioned|was saying|has said|has mentioned|says|told (?:me|us)|let (?:me|us) know|was telling (?:me|us)|reckons|thinks)(?: that)? (?:he|she|they) (wants|needs)\\b",
                        "^((?:the )?[\\w ]+?) (?:has )?(?:ordered|requested)\\b",
                        "^((?:the )?[\\w ]+?)'s (?:order|request)(?: is|:)\\s*",
                        "^(?:request|order) (?:from|for) ((?:the )?[\\w ]+?)\\s*:\\s*(?:one )?",
                    ),
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise1:_wants17": (
        "f6c73ee50a9dd1a9",
        ((), (" could do with", " for h", "borrowing", "due", "hoping to get", "to have"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_when": (
        "0573aa6153e2f1a8",
        ((), ("efore", "y the time"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise1:_where_it_is31s": (
        "9de094626e2d45e4",
        ((), ("th",), True),
        (
            (
                "_WHERE_IT_IS31S",
                (
                    "pattern",
                    "(?:^|(?<=[.!?] ))(?P<see>(?:(?:so |and )?(?:do |can )?you see |see ))?(?P<det>the|that|this) (?P<obj>[a-z]+(?: [a-z]+)?)(?P<loc> (?:by|next to|near|beside|behind|in front of|right by|just by|over by) (?:you|(?:the|your|my|that|this) [a-z]+(?: [a-z]+)?))?(?P<end>\\s*[?,])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise1:_why_said_first": (
        "a8292c39f2375a55",
        (
            (),
            (
                " are both ",
                " back",
                " busy",
                " hands full",
                " it ",
                " lost ",
                " them to ",
                "break",
                "going home",
                "leaving",
                "lunch",
                "off",
                "round",
                "shift",
            ),
            True,
        ),
        (
            (
                "_STATE",
                (
                    "value",
                    "\"(?:(?:'s|is|has|'s got|has got) (?:finishing|starting|ending|off on|going on|on) (?:her|his|their) (?:shift|break|lunch|rounds|round)|(?:'s|is) (?:off home|leaving|going home|off)|(?:'s|has) got (?:his|her|their) hands full|has (?:his|her|their) hands full|(?:'s|is) busy|(?:'s|is) back)\"",
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_will_do31s": (
        "7e4e6e853f83f094",
        (
            (),
            (
                " is fine",
                " is ok",
                " will do",
                " works",
                " would do",
                "'ll do",
                "'s fine",
                "any",
                "either",
            ),
            True,
        ),
        (
            (
                "_FINE_AFTER31S",
                (
                    "pattern",
                    "(?:^|(?<=[.!?] ))(?P<choice>(?:either|any)(?: one)?(?: of (?:the|those|these)(?: two| three| four)?)? [a-z]+(?: [a-z]+)?) (?P<to>for|to) (?P<who>[^,.;!?]+?)(?: will do| would do|'ll do| is fine|'s fine| is okay| is ok| works)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
            (
                "_KIND_FINE31S",
                (
                    "pattern",
                    ",\\s*(?:either|any) (?:colour|color|size|one|kind|sort)(?:'s| is) (?:fine|ok|okay)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
            (
                "_WILL_DO31S",
                (
                    "pattern",
                    "(?:^|(?<=[.!?] ))(?P<choice>(?:either|any)(?: one)?(?: of (?:the|those|these)(?: two| three| four)?)? [a-z]+(?: [a-z]+)?)(?: will do| would do|'ll do| is fine|'s fine| is okay| is ok| works) (?P<to>for|to) (?P<who>[^,.;!?]+?)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise1:_words": (
        "e512d10674669dc6",
        (
            (),
            (
                " also ",
                " asked for",
                " asking for",
                " been after",
                " borrow",
                " due ",
                " end up ",
                " everything else",
                " for ",
                " is for ",
                " is the ",
                " needing",
                " no",
                " of them",
                " possible",
                " so one each",
                " take",
                " to ",
                " wanting",
                " whatever ",
                ", then ",
                "actually",
                "after",
                "after ",
                "any chance ",
                "as soon as ",
                "asap",
                "asked",
                "asked ",
                "at the end",
                "back on ",
                "better",
                "by the end",
                "careful",
                "chop chop",
                "easier",
                "erself",
                "everybody",
                "everyone",
                "first",
                "for ",
                "gentle",
                "hang on",
                "here",
                "hold on",
                "i mean",
                "imself",
                "in",
                "kind",
                "kindly",
                "last",
                "last of all",
                "like,",
                "ma'am",
                "madam",
                "mentioned",
                "mind ",
                "miss",
                "mister",
                "nice",
                "nicely",
                "on the double",
                "once",
                "onto",
                "oops",
                "polite",
                "politely",
                "pronto",
                "quick",
                "quicker",
                "quiet",
                "right now",
                "said",
                "says",
                "sharpish",
                "simpler",
                "sir",
                "sorry",
                "sweetly",
                "tells me",
                "that",
                "them all",
                "to be ",
                "to close",
                "to end with",
                "to finish",
                "to wrap up",
                "told me",
                "wait",
                "waiting",
                "when",
                "which",
                "whichever ",
            ),
            True,
        ),
        (
            ("_REFLEXIVE", ("value", "'(?<=\\\\w) (?:himself|herself)\\\\b'")),
            (
                "_WORDS",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\b(ask(?:ed|ing) for [^.;!?,]*?) (?:twice|three times|several times|a few times|again|already|ages ago|a while ago|a bit ago|earlier|this morning|this afternoon|yesterday|last night|(?:an|one|two|ten|twenty|half an) (?:minutes?|hours?) ago|just now|all day|all morning|all afternoon|all evening|all week|all lesson|all class|all shift|all session|all practice|all rehearsal|all meeting|all match)(?: long)?(?: now| today| already)?(?=\\s*(?:[.,;!?]|$))",
                        ",?\\s*\\b(?:sharpish|pronto|asap|chop chop|on the double)\\b",
                        "\\s*(?:\\bis|'s|\\bare|'re|\\bwas|\\bhas been|'s been|\\bhave been|'ve been) (?:still )?waiting(?: ages| forever| a while| so long)? for\\b",
                        "\\s*(?:\\bwas|\\bwere|\\bis|\\bare|'s|\\bhas been|'s been) asking for\\b",
                        "\\s*(?:\\bhas|\\bhave|\\bhad|'s|'ve) asked for\\b",
                        "(?<=\\w) asked for\\b(?= (?:the|a|an|some)\\b)",
                        "^(.+?)'s (\\w+) is the (\\w+) one\\b",
                        "^(give|hand|pass|bring) (?:all (?:two|three|four|five) of them|each of them|them all|everyone|everybody|all of them) (?:an? (?:item|thing|object)|something)(?: each)?:\\s*",
                        "(?:^|(?<=[.!?;])\\s*)(?:sorry,? )?i mean(?:t)? [^.!?;]*[.!?;]\\s*no,? (?:actually,? )?(?:the )?\\w+(?: \\w+)? (?:was|is) (?:right|correct|fine|ok)[.!?]?",
                        "([;,]\\s*(?:and )?[A-Z][\\w ]*?),\\s*for (?=the |a |an )",
                        "(?<=\\w) no,? (?=the |a |an )",
                        ",\\s*(?!the |a |an )(\\w+) (last|first)\\b",
                        "\\bwhichever (\\w+) (?:is|'s) (on|in) ",
                        "\\b(?:that|which)(?:'s| is| are|'re)? (?:sitting|lying|standing|resting|kept) (on|in)\\b",
                        "\\blast of all\\b",
                        "(^|(?<=[.;!?])\\s*)(?:to finish|to end with|at the end|to close|to wrap up),",
                        "\\s*(?:\\bhas|'s) been after\\b",
                        "\\s*(?:\\bis|\\bare|'s|'re) needing\\b",
                        "\\s*(?:\\bis|\\bare|'s|'re) wanting\\b",
                        "\\s*(?:\\bis|\\bare|'s|'re) (?:supposed|meant|due) to (?:get|have|receive)\\b",
                        "\\b(?:has|have|had)(?: got)? to (?:get|have|receive)\\b",
                        "^(.+?) (gets|can have|should get|takes) whatever (.+?) (?:doesn't|does not|don't|won't|isn't)(?: get| take| have| want)?\\s*[:;,-]\\s*(.+?)[.!]?$",
                        ",?\\s*(?:and )?after (?:both|all|those|these|them|both of them|all of them) (?:are|have been|were) (?:done|finished|complete|completed),?",
                        "(^|(?<=[.;!?])\\s*)(?:is there )?any chance (?:of|for) ",
                        ",?\\s*\\b(?:as soon as (?:possible|you can)|when(?:ever)? possible)\\b",
                        ",?\\s*\\bby the end(?: of (?:the |this |today's |your )?\\w+)?\\b",
                        ",\\s*like,",
                        ",?\\s*\\bright now\\b,?",
                        ",?\\s*\\bif (?:that's|that is|it's|it is) (?:easier|simpler|better|quicker)\\b",
                        "(^|(?<=[.;!?])\\s*)(?:so |and )?be (?:nice|quick|careful|gentle|polite|kind|quiet)\\b(?:\\s*[:,]|\\s+and\\b)?\\s*",
                        ",?\\s*\\b(?:so |and )?be (?:nice|quick|careful|gentle|polite|kind|quiet)\\b(?:\\s*[:,])?",
                        ",\\s*(?:very |so |quite |really |rather |most |extremely )?(?:politely|nicely|kindly|sweetly)\\s*,",
                        "\\s*(?:\\bhas |\\bhave |\\bhad |'s |'ve )?asked,? (?:whether|if) (?:she|he|they) (?:could|might|may|can) (?:have|get)\\b",
                    ),
                ),
            ),
            (
                "_WORDS_LATE",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\b((?:once|when|after) (?:he|she|they)(?:'s| has| have|'ve)? (?:got|had|taken|received|gotten) (?:them|it|those|that))\\s+(?=(?:give|hand|pass|bring|put|place)\\b)",
                        "\\b(?:back )?(?:in|into|onto) (?=the )",
                        "\\bback on (?=the )",
                        "\\s*(?:\\bis|'s|\\bare|'re) due (?:his|her|their|the)?\\b",
                        "(?<=\\w) also (?=(?:wants|needs|would like|'d like|gets|should get|could have|can have)\\b)",
                        "^(?:please )?(?:leave|don't touch|do not touch) (the [\\w ]+?)(?: alone| where they are| be)?,? (?:and|but) (give|hand|bring) ([\\w ]+?) everything else\\b",
                        "^([A-Z][\\w ]*?) (?:said|says|mentioned|told me|tells me)(?: that)? (?:he|she|they) (?=(?:needs|wants|would like|'d like|could use|'s after)\\b)",
                        "\\bboth (want|need|would like)s? (a|an|one) ([\\w ]+?),? so one each\\b",
                        "^(?:(?:ok|okay|so|well|right|literally|basically|honestly|just),?\\s+)*(?:what|all) (?:i|we) (?:need|want|would like|'d like) is for ([A-Z][\\w ]*?) to (get|have|receive)\\b(?= (?:the|a|an|both|all|one)\\b)",
                        "^(?:(?:ok|okay|so|well|right|literally|basically|honestly|just),?\\s+)*(?:what|all) (?:i|we) (?:need|want|would like|'d like) is for ",
                        "^([A-Z][\\w ]*?) (can|may|could) take\\b(?=(?:(?!\\b(?:to|on|onto|in|into|over)\\b)[^.;!?])*[.!?]?$)",
                        "(?<!needs )(?<!need )(?<!has )(?<!have )\\bto be (on|in|onto)\\b",
                        "\\b(?:has to|have to|should|must|needs? to) end up (on|in|onto)\\b",
                        "\\bwhichever ((?:she|he|they|you) (?:likes?|wants?|prefers?|fancies|fancy)),\\s+((?:the |a |an |either )?[^,.;!?]+?\\bor\\b[^,.;!?]+)",
                        "\\b(everything|(?:all the|every|each) (?:objects?|things?|items?)) (?:here|in here)\\b",
                        "\\b((?:hang on|hold on|no wait|wait|actually|sorry|oops)(?:,? (?:no|wait))?),\\s+(?:since |because |as )?(?:she|he|they)(?:'s| is| has|'ve| have| are|'re| already)\\b[^,;.!?]*?,\\s*(?=(?:take|give|hand|bring|put|place|pass|send)\\b)",
                        "\\b(can|could|may|might) (?!(?:you|we|i|u)\\b)(\\w+(?: \\w+)?) borrow\\b",
                        "^(?:miss|sir|madam|ma'am|mister|missus)\\s*[,:]\\s*",
                        "(^|(?<=[.;!?])\\s*)mind (?=\\w+ing\\b)",
                        "\\b(would like|'d like|would love|'d love|wants|want|needs|need) to (?:have|get|receive) (?=(?:the|a|an|some|both|one|all|either|any)\\b(?:(?!\\b(?:to|on|onto|in|into|for)\\b)[^.;!?])*(?:[.;!?]|$))",
                        "\\basked (it|them|that)(?=\\s*[,;.])",
                        "^(the [\\w ]+?), then (the [\\w ]+?),? both (to|on|onto) ([\\w ]+?)[.!]?$",
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise1:_wrappers": (
        "defaa2539365df71",
        (
            (),
            (
                " been ",
                " borrow",
                " it if ",
                " that ",
                " to be",
                "a bother",
                "a hassle",
                "a problem",
                "an issue",
                "and that ",
                "any trouble",
                "anybody",
                "anyone",
                "arrange for ",
                "asked ",
                "brought",
                "furnished",
                "given",
                "grateful",
                "handed",
                "is there any ",
                "obliged",
                "ought to",
                "passed",
                "provided",
                "sent",
                "somebody",
                "someone",
                "supplied",
                "thankful",
                "that ",
                "too much ",
                "upon",
                "wondering ",
                "would it be ",
            ),
            True,
        ),
        (
            (
                "_WRAPPERS",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\b(?:is|are|was|were|am) to be\\b",
                        "\\bought to\\b",
                        "\\bwould it be (?:at all |even )?(?:possible|ok|okay|alright) for (.+?) to be (taken|brought|given|handed|put|placed|moved|delivered|sent|passed)\\b",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:so,?\\s+)?is there any (?:chance|way|possibility) (?:that )?",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)would it be (?:possible|ok|okay|alright) for (.+?) to (?:borrow|have|get|take) ",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:i|we) (?:was|were|am|are) (?:just )?wondering (?:if|whether) ",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:i|we) (?:would|'d|should) be (?:most |very |really |so |extremely )?(?:grateful|thankful|obliged) if ",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:please |kindly )?(?:ensure|make sure|see to it) that ",
                        ",\\s*and that ",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:please |kindly )?arrange for (.+?) to be ",
                        "\\bupon\\b",
                        "\\b(would|'d|will) be (?:(?:most|very|really|so|extremely|ever|awfully|terribly) )*(?:grateful|thankful) for\\b",
                        "\\b(?:could|can|should|might|will) be (?:provided|supplied|furnished) with\\b",
                        "\\b(?:could|can|should|might|will|must) (?:please )?be (?:given|handed|passed|brought|sent)\\b(?!\\s+(?:to|over|across|back|on|onto)\\b)",
                        "^(could|can|would|will|might|must|should) ((?:the )?[\\w ]+?) (?:please )?be (?:given|handed|passed|brought|sent)\\b(?!\\s+(?:to|over|across|back|on|onto)\\b)",
                        "\\b(?:has|have|had|'s|'ve) been (?:given|handed|passed|brought|sent)\\b(?!\\s+(?:to|over|across|back|on|onto)\\b)",
                        "\\b(could|can|may|might) borrow\\b",
                        "\\basked (?:whether|if) (?:she|he|they) (?:could|might|can|may) (?:have|get)\\b",
                        "\\b(could|can|would|will) (?:someone|somebody|anyone|anybody)\\b",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:i|we)(?:'d| would) (?:love|like|prefer) it if ",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:please )?see (?:to it )?that ",
                        "(^|(?<=[.;!?:])\\s*|(?<=,)\\s*(?:and\\s+)?)(?:would|will|is) it be (?:a problem|an issue|a bother|a hassle|any trouble|too much (?:trouble|bother|hassle)) (?:for you )?to (?:(let) )?",
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise2:_a_typo28": (
        "31350f855fc82c23",
        ((), ("a",), True),
        (("_A_TYPO28", ("pattern", "^(a|an) ([a-z]{4,})(?= (?:for|to) )", 34)),),
    ),
    "hltl.grounding._normalise2:_according33": (
        "c2e65c03b9b4783a",
        (("according",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_add_to32": ("2d1a667127766b69", ((), ("add ",), False), ()),
    "hltl.grounding._normalise2:_address_after26r": (
        "988bb08c9e1414a6",
        ((), ("ma", "sir"), True),
        (
            (
                "_ADDRESS_AFTER26",
                ("pattern", "\\s+(?:ma'am|ma’am|maam|madam|sir)(?=\\s*[,.;!?]|$)", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_after_doing34": (
        "00b816ab26f97eae",
        ((" after ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_after_it35": ("9fe7ae70bf49c84c", ((), ("after it",), False), ()),
    "hltl.grounding._normalise2:_after_pastime35": (
        "3dac87d0349a8135",
        ((" after ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_after_state31": (
        "2749d23f6c9a1029",
        ((), ("after", "since"), True),
        (
            (
                "_AFTER_STATE31",
                (
                    "pattern",
                    "^(?:after|since) (?P<what>(?:the|his|her|their|a|an) [a-z][a-z' ]*?),?\\s+(?=(?P<p>[A-Za-z]+(?: [A-Za-z]+)?)(?:'s| is) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_all_listed30": (
        "127285eb2d3072a3",
        (
            (),
            ("all of it", "all of that", "all of them", "everything", "the lot", "the whole lot"),
            True,
        ),
        (
            (
                "_ALL_LISTED30",
                (
                    "pattern",
                    "(?P<all>\\b(?:all of it|all of them|everything|the lot|the whole lot|all of that)\\b(?='s|\\s+(?:is|are|goes|go|to|for|on|onto|in|into|over|across)\\b|\\s*[,.;!?]|\\s*$)[^.;!?]*?),\\s*(?:that's|that is|which is|which are|i\\.e\\.|meaning|namely)(?: just| only)? (?P<list>[^.;!?,]+?(?:,[^.;!?,]+?)*)\\s*(?=[.;!?]|$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_all_yours33": (
        "bfbace7d16e80a75",
        (("all yours",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_along_with31": (
        "13f270c1e479c757",
        ((), ("along with",), False),
        (),
    ),
    "hltl.grounding._normalise2:_along_with35": ("1858ef07bd1b2410", ((" with ",), (), False), ()),
    "hltl.grounding._normalise2:_announced36": ("382a40a27e1628ce", ((), ("robot",), False), ()),
    "hltl.grounding._normalise2:_apology26": (
        "f49dc1b45d69db25",
        ((), (" sorry",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_apposition31": ("8898bc4a14d8f073", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_archaic19": (
        "d601fbabf496ad4b",
        (
            (),
            (
                " should be ",
                " with",
                "across",
                "aloft",
                "along",
                "arrives ",
                "bear ",
                "canst thou",
                "craveth",
                "desireth",
                "doth ",
                "ends up with",
                "gets to",
                "hath",
                "make sure",
                "nay",
                "prithee",
                "reaches",
                "rest ",
                "round",
                "see that ",
                "see to it that",
                "shall ",
                "shall be ",
                "take delivery of",
                "thee",
                "there",
                "thou",
                "through",
                "to the ",
                "unto",
                "wanteth",
                "wilt",
                "wilt thou",
                "wouldst",
                "wouldst thou",
                "ye",
            ),
            True,
        ),
        (
            (
                "_archaic19_words",
                (
                    "guarded",
                    "hltl.grounding._normalise2:_archaic19_words",
                    "04ef48b7a22f0009",
                    (
                        (
                            "_ARCHAIC19_WORDS",
                            (
                                "patterns",
                                "pairs",
                                (
                                    "\\bwouldst thou\\b",
                                    "\\bwilt thou\\b",
                                    "\\bcanst thou\\b",
                                    "\\b(?:thou|thee|ye)\\b",
                                    "\\bwouldst\\b",
                                    "\\bwilt\\b(?! (?:flower|leaf))",
                                    "\\bdoth (?:desire|want|crave|wish for)\\b",
                                    "\\b(?:craveth|desireth|wanteth)\\b",
                                    "\\bhath\\b",
                                    "\\bshall be (given|handed|passed|brought|placed|put|taken)\\b",
                                    "\\bshall (have|get|receive)\\b",
                                    "\\b(?:thereafter|thereupon)\\b",
                                    "\\bunto\\b",
                                    "\\bto the (?:very )?same(?: (?:player|person|one|fellow|chap|lady|gentleman|guy))?\\b",
                                    "\\bprithee\\b",
                                    "\\bnay\\b",
                                    "(?<!teddy )\\bbear (?=the |it\\b|them\\b)",
                                    "\\b(?:supply|furnish|provide|equip|present) ([A-Z][\\w ]*?) with\\b",
                                    "^(?:please )?(?:make sure|ensure|see to it that|see that) (.+?) (?:reaches|gets to|arrives (?:at|with)|ends up with) ",
                                    "^(?:could|can|would|will) you (?:please )?see that (.+?) (?:reach|reaches|get to|gets to) ",
                                    "\\b(?:see to it that|make sure that|make sure) ([A-Z][\\w ]*?) (?:receives|gets) ",
                                    "(?<!the )\\brest (it|them|the [a-z ]+?) (on|onto|in|into|upon|atop)\\b",
                                    "\\btake delivery of\\b",
                                ),
                            ),
                        ),
                        (
                            "_sub",
                            ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77"),
                        ),
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise2:_as_for34": (
        "78a1a619d8c73449",
        ((), ("as ",), True),
        (
            (
                "_AS_FOR34",
                (
                    "pattern",
                    "(?:^|(?<=[.;!?])\\s+)as (?:for|regards|to) (?P<x>(?:the|that|this|those|these) [^,.;!?]+?),\\s*(?P<rest>[^.;!?]*)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_as_used_to34": ("ca5bcf9bc9ed58c5", ((" say",), (), False), ()),
    "hltl.grounding._normalise2:_as_we_say31": ("1aa6e947dee5b5cf", ((), (" say ",), False), ()),
    "hltl.grounding._normalise2:_asked36": (
        "a16347420987853f",
        (
            (" out ",),
            ("any chance of ", "do you reckon", "i wonder if", "i wonder whether", "you think"),
            True,
        ),
        (
            (
                "_ANY_CHANCE36",
                (
                    "pattern",
                    "^(?:is there )?any chance of (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:for|going to|going over to|over to|to) (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?=\\s*[,?])",
                    34,
                ),
            ),
            (
                "_THINK_MANAGE36",
                (
                    "pattern",
                    "^(?:do you think|d'you think|do you reckon|you think|I wonder if|I wonder whether) you (?P<ask>could|can) manage (?=[a-z])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_asked_after32": (
        "6773e810add086b7",
        ((), (" where ", "back from"), False),
        (),
    ),
    "hltl.grounding._normalise2:_asked_as32": (
        "778d2d5ebd1c60be",
        ((), (" if ", " suppose you", " we say", "find "), True),
        (
            (
                "_BE_GOOD32",
                (
                    "pattern",
                    "^(?:(?:it|that)(?:'d| would) |would )?be (?:good|great|nice|lovely|handy|grand|brilliant|ace) if (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:could|can|would) (?P<v>get|have|take) (?P<rest>[^,?!.]+?)\\s*(?P<end>[?.!]?)\\s*$",
                    34,
                ),
            ),
            ("_FIND_WAY32", ("pattern", "\\bfind (?P<pos>its|their) way\\b", 34)),
            (
                "_SHALL_WE_SAY32",
                ("pattern", "^(?:shall|should) we say,? (?:that )?(?P<rest>[^?]+)\\?\\s*$", 34),
            ),
            (
                "_SUPPOSE32",
                (
                    "pattern",
                    "(?:^|(?<=[.!?]\\s))(?:I )?(?:don't|do not) suppose (?:you could|you'd|you would)\\b",
                    34,
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_asked_as33": ("e7b68c69a415283b", (("?",), (), False), ()),
    "hltl.grounding._normalise2:_at_table30": (
        "7fe2c8f4951aba8f",
        ((), (" at ", " in ", " on "), False),
        (),
    ),
    "hltl.grounding._normalise2:_back_from_place32": (
        "783967450724000f",
        ((), ("back from ",), True),
        (
            (
                "_BACK_FROM_PLACE32",
                (
                    "pattern",
                    "^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:is|'s) (?:just )?back from (?:the|his|her|their) [a-z]+(?= *[,;.])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_been_at34": ("edcf4d12d124aa0b", ((" been ",), (), False), ()),
    "hltl.grounding._normalise2:_been_wanting32": (
        "10626d60e259744a",
        ((" been ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_before_deadline32": (
        "d6806ec796d5fe94",
        ((), ("before",), False),
        (),
    ),
    "hltl.grounding._normalise2:_beside_on32": (
        "e0406c42140cf665",
        (("alongside", "beside", "next to"), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_better_home35": (
        "34f37fb643dbef5c",
        ((), (" there",), True),
        (
            (
                "_BETTER_HOME35",
                (
                    "pattern",
                    "^(?:would|wouldn't|might|could) (?P<s>the [a-z][a-z ]*?) (?:be|make) a (?:better|good|nice|decent|safer|tidier) (?:home|place|spot|resting place) for (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)\\s*\\?\\s+(?:so\\s+)?(?:pop|put|stick|place|set|pop|move) (?P<pron>it|them)(?: up| down| over)? there\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_both_after28": ("d297f46b78eab33e", ((), (" both ",), False), ()),
    "hltl.grounding._normalise2:_brought26": (
        "930be14a0f6a0593",
        ((), ("brought", "fetched", "passed", "sent"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_by_any_chance30": (
        "b6b0f6bc24f2b91f",
        ((), ("chance",), False),
        (),
    ),
    "hltl.grounding._normalise2:_by_landmark33": (
        "3eab0ea2db59547a",
        (("beside", "by", "near", "next to"), (), True),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise2:_by_surface35": (
        "7ea75457236b32ac",
        ((" is ", "'s "), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_can_take30": ("c8cfa2b4a3e236da", ((), (" can ",), False), ()),
    "hltl.grounding._normalise2:_care35": ("1da351db281e5209", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_choices26": (
        "7ee6fb40589e428d",
        ((), ("any ", "both ", "both of them", "the pair of them", "the two of them"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_clear_up32": (
        "d550ef185778273a",
        ((), (" you",), True),
        (
            (
                "_CLEAR_UP32",
                (
                    "pattern",
                    ",?\\s+(?:when|while|as) you(?:'re| are)? (?:clear|tidy|clearing|tidying) (?:up|away)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_cleft30": ("a9ad101084fcfd93", ((), ("it",), False), ()),
    "hltl.grounding._normalise2:_cleft_wants31": (
        "8331a5e8199db644",
        ((), (" what ", "for "), False),
        (),
    ),
    "hltl.grounding._normalise2:_cleft_who33": ("5c76eb3836111bbb", ((" who ",), (), False), ()),
    "hltl.grounding._normalise2:_clefts35": ("480ed8c541fa724b", ((), ("it",), False), ()),
    "hltl.grounding._normalise2:_closing_cause33": ("3983b1d549552495", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_corrected_first26": (
        "262b2ba2c5f9e91d",
        ((), ("the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_counted26": (
        "ae6ff63f9aba842b",
        ((), ("them all", "them both"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_courtesies36": (
        "301c8b553877f38a",
        ((), (" favo", " from ", " if you", " of you"), True),
        (
            (
                "_FAVOUR36",
                (
                    "pattern",
                    "^(?:a |one )?(?:quick|small|little|tiny|wee) favou?r(?: to ask)?(?: (?:before|ahead of) my (?:(?P<act>[a-z]+(?: [a-z]+)?) )?(?:lesson|class|practice|rehearsal|session|shift|appointment|match|game|run|swim|walk|meeting))?\\s*:\\s*",
                    34,
                ),
            ),
            (
                "_GOOD_OF_YOU36",
                (
                    "pattern",
                    "^(?:(?:that's|that is|it's|it is|how|so|very|really|ever so|too) )*(?:kind|good|nice|sweet|decent|lovely|thoughtful|generous) of you(?:,\\s*(?:really|truly|honestly))?\\s*[,.!]\\s*",
                    34,
                ),
            ),
            (
                "_OBLIGED36",
                (
                    "pattern",
                    "^(?:much obliged|most obliged|(?:I'd|I would|I'll|I will|we'd|we would) be (?:much |most |very |ever so )?obliged) if you(?:'d| would| could)(?: kindly)? (?=[a-z])",
                    34,
                ),
            ),
            (
                "_THANKS_GROUP36",
                (
                    "pattern",
                    ",\\s*(?:and\\s+)?(?:thanks|thank you|cheers|many thanks)(?: a million| a bunch| a lot| very much| so much| loads)? from (?:the whole|all the|all of the|everyone in the|everyone at the|the) (?P<what>[a-z]+ )?(?:class|club|team|group|crew|choir|band|troupe|squad|gang|lot|staff|family)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_courtesy_please33": (
        "cf7cd4de7c73cfb5",
        (
            (),
            (
                "a",
                "big up",
                "bless up",
                "bun",
                "cies",
                "cze",
                "dzi",
                "e se",
                "hei",
                "hej",
                "innit",
                "istuti",
                "khrub",
                "kiitti",
                "krub",
                "kuji",
                "kuju",
                "leh",
                "meh",
                "merci",
                "mersi",
                "mesi",
                "milesker",
                "o",
                "permisi",
                "privet",
                "pryvit",
                "r ederim",
                "respect",
                "sthuthi",
                "stuthi",
                "sveiki",
                "sz",
                "tenkyu",
                "tere",
                "tesekkurler",
                "umesc",
                "xie xie",
            ),
            True,
        ),
        (
            (
                "_COURTESY24",
                (
                    "value",
                    "'habari(?: yako| gani)?|jambo|hujambo|sawasdee|sawatdee|sawasdi|dobryi den|dobryy den|dobry den|dobriy den|pryvit|vitayu|selamat (?:pagi|petang|siang|malam|datang)|apa khabar|merhaba|yassou|yassas|geia sou|xin chao|kumusta|kamusta|magandang (?:umaga|hapon|gabi)|namaste|namaskar|salaam|salam|as-?salaamu? alaikum|shalom|hola|bonjour|ciao|konnichiwa|ni hao|kia ora|sawubona|ahoj|asante(?: sana)?|khop khun(?: mak)?|khob khun(?: mak)?|kop khun|diakuiu|dyakuyu|diakuyu|spasibo|terima kasih|salamat|tesekkurler|efharisto|efcharisto|cam on|dhanyavaad|dhanyavad|shukriya|shukran|gracias|merci(?: beaucoup)?|grazie(?: mille)?|danke(?: schon)?|arigato(?: gozaimasu)?|xie xie|obrigado|obrigada|dziekuje|diolch|toda|kiitos|mamnoon|mamnun|khahesh mikonam|terima kasih banyak|makasih|köszönöm|koszonom|köszi|koszi|jó napot(?: kívánok)?|jo napot(?: kivanok)?|szia|permisi|sudah|terserah|mas|mbak|bless up|big up|respect|one love|dobrý den|dobry den|děkuji|dekuji|děkuju|dekuju|bună ziua|buna ziua|bună|mulțumesc|mulţumesc|multumesc|mersi(?: mult)?|vanakkam|vanakam|nandri|nanri|chale|medaase|akwaaba|gamarjoba(?:t)?|(?:didi )?madloba|genatsvale|nakhvamdis|labas(?: rytas| vakaras)?|laba diena|ačiū(?: labai)?|aciu(?: labai)?|tena yistilign|tena yistiligne|tena yistilgn|selam(?: new)?|(?:betam )?(?:ameseginalehu|amesegnalehu|ameseginalew)|ayubowan|(?:bohoma )?(?:sthuthi|sthuthiy|stuthi|isthuthi|istuti)|labdien|paldies|sveiki|tere|aitäh|aitah|tänan|tanan|barev(?: dzez)?|shnorhakalutyun|sağ ?ol|sag ?ol|çox sağ ?ol|chox sag ?ol|hvala(?: lijepa| puno| vam)?|zdravo|dobar dan|dzień dobry|dzien dobry|cześć|czesc|dziękuję|privet|zdravstvuyte|blagodaryu|blagodarya|tack(?: så mycket| sa mycket)?|takk|tusen takk|mange tak|hej|hei|dank je(?: wel)?|dank u(?: wel)?|bedankt|goedemorgen|goedemiddag|annyeonghaseyo|annyeong|kamsahamnida|gamsahamnida|gomawo|mingalaba|mingalarba|dhanyabad|dhonnobad|nomoskar|sat sri akal|sannu|na gode|daalu|ndewo|ngiyabonga|siyabonga|enkosi|mahalo(?: nui)?|aloha|toda raba|marhaba|ahlan(?: wa sahlan)?|teşekkür ederim|tesekkur ederim|olá|bom dia|buenos (?:días|dias)|buenas tardes|muchas gracias|e kaaro|e kaasan|e kaale|e ku aaro|e ku irole|e se(?: gan| o)?|o se(?: gan| o)?|ole hyvä|ole hyva|moi|kiitti|faleminderit|grazas|moitas grazas|meur ras|zikomo(?: kwambiri)?|mesi(?: anpil)?|malo aupito|mālō aupito|sulpayki|añay|anay|tenkyu(?: tru)?|kadrinchey(?: la)?|kadrin chhe(?: la)?|natotela(?: sana)?|ua tsaug(?: ntau)?|ke a leboga|kea leboga|kealeboga|eskerrik asko|mila esker|milesker|gràcies|gracies|moltes gràcies|moltes gracies|ďakujem(?: pekne)?|dakujem(?: pekne)?|vďaka|vdaka|bless you|amen(?: to that)?|inshallah|mashallah|pole pole|innit|khrap|khrub|krap|krub|hor|kha|lah|leh|lor|meh|opo|paa|sha|ah|ja|la|po|o'",
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise2:_described29": ("d2656c741d3902ed", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_do_that34": ("20bdb2d4971a3232", (("so do ",), (), False), ()),
    "hltl.grounding._normalise2:_doing25": (
        "685d32d139faf3d4",
        ((), (" to",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise2:_done_with34": (
        "402edb2774a65aa5",
        ((" done", " finished"), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_dropped_is36": ("4c684f64082f4713", (("s ",), (), False), ()),
    "hltl.grounding._normalise2:_dyou30": ("d3ee3155df180abf", ((), ("d'",), False), ()),
    "hltl.grounding._normalise2:_each_wants32": (
        "dda7693b3f623178",
        ((), ("a thing", "one thing", "something"), True),
        (
            (
                "_EACH_WANTS32",
                (
                    "pattern",
                    "^(?:they|the two of them|both of them|the pair of them|these two|those two) (?:each |both )?(?:want|need|would like|are after|have asked for) (?:something|a thing|one thing)(?: each)?\\s*:\\s*",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_earned_after33": (
        "081893110d304ade",
        ((" after ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_event_time33": ("e9ba8120f966fbc5", ((), ("for ",), False), ()),
    "hltl.grounding._normalise2:_ever_since30": (
        "67a5a37ba2995eee",
        ((), ("ever since",), False),
        (),
    ),
    "hltl.grounding._normalise2:_first_over31": ("8ad8f9f76d85b4b4", ((), ("first",), False), ()),
    "hltl.grounding._normalise2:_for_bare31": (
        "20912df0f08dc6f4",
        ((), (" for ",), True),
        (
            (
                "_FOR_BARE31",
                (
                    "pattern",
                    "(?P<s>\\b(?:on|onto|in|into|on top of) (?:the )?[a-z]+(?: [a-z]+)?) for (?P<w>[a-z]+)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_for_his34": (
        "d8240270c5f0020c",
        (("or ",), (), True),
        (
            (
                "_FOR_HIS34",
                (
                    "pattern",
                    "^[Ff]or (?P<pron>his|her|their) (?P<what>[a-z]+(?: [a-z]+){0,2}),? (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?=(?:is going to need|is gonna need|will need|needs|wants|is after|would like)\\b)",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_for_to_do32": ("b85f4a350c775046", ((" for ",), (), False), ()),
    "hltl.grounding._normalise2:_for_whose28": ("4d251748fe2637f8", (("'s ",), (), False), ()),
    "hltl.grounding._normalise2:_from_trade34": ("bda9c054e0b50507", (("from ",), (), False), ()),
    "hltl.grounding._normalise2:_get_sorted35": ("557cba73e405657b", (("so ",), (), False), ()),
    "hltl.grounding._normalise2:_give_them_those36": (
        "5536c786f75733d4",
        (("'em", "them"), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_hand_over32": (
        "2001cda4fd9e1cd1",
        ((), (" you ",), True),
        (
            (
                "_HAND_OVER32",
                (
                    "pattern",
                    ",\\s*(?:can|could|would|will) you (?P<v>hand|pass|give|bring) (?P<o>it|them) over\\s*\\?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_handed28": (
        "213365c0003f1597",
        ((), (" hand", " palm", " something", " them ", "make it", "out of the way"), True),
        (
            (
                "_GIVE_THEM28",
                ("pattern", "\\b(give|hand|pass|bring|fetch|get) them (?=(?:the|a|an|both) )", 34),
            ),
            (
                "_SOMETHING28",
                (
                    "pattern",
                    "^(both|all|each) of the ([a-z]+(?: [a-z]+)?) (wants?|needs?) something\\s*:",
                    34,
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise2:_handover_frames34": (
        "f4aabb1067b58373",
        ((" hands", " the one "), (" to",), True),
        (
            (
                "_TROT34",
                (
                    "pattern",
                    "\\b(?:trot|scoot|nip|zip|run|whizz) (?P<x>it|them|(?:the|that|this|those|these) [a-z][a-z ]*?) (?:over|down|up|across|along|round) to\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_has_coming34": (
        "8cd6d684ae43c31b",
        ((" coming", " owed "), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_has_going30": ("465d668a0ccebb0e", ((), (" got ",), False), ()),
    "hltl.grounding._normalise2:_headed26": (
        "e224246e4ee68428",
        ((), ("clear ", "need", "want"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_headed_for35": (
        "a9385e0cde9d87ff",
        (("bound", "destined", "earmarked", "head"), (), True),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise2:_header_count20": (
        "de0eb4677b4cf69f",
        ((), ("deliveries", "job", "request", "task", "thing"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise2:_her_surface31": (
        "2f8decb7b0ec8e3d",
        ((), ("her", "his", "their"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise2:_his_way32": ("058223ff72e28436", ((" way",), (), False), ()),
    "hltl.grounding._normalise2:_how_about30": ("37056ac5fe11891a", ((), ("about",), False), ()),
    "hltl.grounding._normalise2:_idioms30": (
        "400920448e02efd7",
        ((), (" eye", "begging", "could ", "crying", "gasping", "grizzling", "pining"), True),
        (
            (
                "_IDIOMS30",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\bcould (?:murder|kill for|really murder) an? (?:drink|cuppa|brew|coffee|tea|pint|cold one)\\b",
                        "\\bcould (?:murder|kill for|really murder) an? (?:sandwich|snack|bite|biscuit|butty|sarnie)\\b|\\bcould eat a horse\\b",
                        "(?:\\s+has|'s) (?:had |got )?(?:her|his|their) eyes? on\\b",
                        "(?:\\s+is|'s|\\s+has been|'s been) (?:grizzling|crying|crying out|pining|gasping|begging) for\\b",
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise2:_idioms31": (
        "d1a9ac574f2fbeea",
        ((), ("earned", "eyeing", "owed"), True),
        (
            (
                "_IDIOMS31",
                (
                    "patterns",
                    "pairs",
                    (
                        "(?:\\s+is|'s) (?:still )?owed\\b(?= (?:the|that|this|those|these|her|his|their)\\b)",
                        "(?:\\s+has|'s) (?:really |more than |well and truly )?earned\\b(?= (?:the|that|this|those|these|her|his|their)\\b)",
                        "(?:\\s+has|'s|\\s+is) (?:been )?eyeing(?: up)?\\b(?= (?:the|that|this|those|these)\\b)",
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise2:_idioms32": (
        "7615741183324178",
        ((), (" been asking ", " set on", "asking ", "fancy "), True),
        (
            (
                "_IDIOMS32",
                (
                    "patterns",
                    "pairs",
                    (
                        "(?:\\s+has|'s) (?:got )?(?:her|his|their) hearts? set on\\b(?= (?:the|that|this|those|these)\\b)",
                        "\\s+(?:keeps|kept) (?:on )?asking (?:for|after)\\b(?= (?:the|that|this|those|these)\\b)",
                        "(?:\\s+has|'s) been asking (?:for|after)\\b(?= (?:the|that|this|those|these)\\b)",
                        "(?:\\s+has|'s) (?:got |taken )?a (?:real )?fancy (?:for|to)\\b(?= (?:the|that|this|those|these)\\b)",
                    ),
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_idioms33": (
        "338fdcdce07bc68b",
        ((), (" asking after", "could "), True),
        (
            (
                "_IDIOMS33",
                (
                    "patterns",
                    "pairs",
                    (
                        "\\s+could (?:really |happily |easily |just |so )?murder\\b(?= (?:the|that|this|those|these)\\b)",
                        "(?:\\s+is|'s|\\s+was) asking after\\b(?= (?:the|that|this|those|these)\\b)",
                    ),
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_idioms34": (
        "c2d890d33b4591ad",
        ((), (" craving for", " wanted over by", "gasping for", "intended", "meant"), True),
        (
            (
                "_IDIOMS34",
                (
                    "patterns",
                    "pairs",
                    (
                        "(?:\\s+is|'s|\\s+was) (?:absolutely |just |really )?gasping for\\b(?= (?:the|that|this|those|these)\\b)",
                        "(?:\\s+has|'s)(?: got)? (?:a|such a|a real|a big) craving for\\b(?= (?:the|that|this|those|these)\\b)",
                        "\\s+(?P<be>is|are) wanted over by\\b(?= [A-Z])",
                        "\\s+(?P<be>is|are) (?:meant|intended) for\\b(?= [A-Z])",
                    ),
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_if_manage31": (
        "9cc6f5d5209fb7c4",
        ((), ("if you c",), True),
        (
            (
                "_IF_MANAGE31",
                (
                    "pattern",
                    ",\\s*if you (?:can|could) (?:manage|handle|carry) (?P<what>both|it|that|them|all that|the two)(?: (?:of them|at once|together))?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_if_so_good28": (
        "8cc40907120d439e",
        ((), (". if ", "if "), False),
        (),
    ),
    "hltl.grounding._normalise2:_if_sort35": ("21ca71af24666e02", ((" if ",), (), False), ()),
    "hltl.grounding._normalise2:_if_spare34": (
        "674061d8faf564f1",
        ((), ("going begging", "not being used", "not needed", "spare"), True),
        (
            (
                "_SPARE34",
                (
                    "pattern",
                    "\\s+if (?:it's|it is|they're|they are) (?:going spare|going begging|spare|not being used|not needed)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_interjected31": (
        "fcccf27e689edf16",
        ((), ("ah", "aw", "er", "hmm", "oh", "uh", "um", "well"), True),
        (
            (
                "_INTERJECTED31",
                (
                    "pattern",
                    "^(?:oh|ooh|ah|aah|aw|ooh la la|oh dear|well|hmm|um|erm|er|uh)\\s*,\\s*(?=(?:could|would|can|will|might|may) (?:you|someone|somebody|one of you)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_is_the_and32": (
        "fe19e3ec39e2e82f",
        ((), (" is the ",), True),
        (
            (
                "_IS_THE_AND32",
                (
                    "pattern",
                    "^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) is the (?P<trade>[a-z]+) and (?P<pron>she|he|they)(?P<want>'d like|'d love| would like| wants| needs| is after)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_it_her31": (
        "c7260e79b709e89e",
        ((), ("bring", "fetch", "give", "hand", "pass", "send", "take"), True),
        (
            (
                "_IT_HER31",
                (
                    "pattern",
                    "\\b(?P<v>bring|give|hand|pass|take|fetch|send) (?P<x>it|them) (?P<p>her|him|them)\\b(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_keep_going33": ("d484abae809e713d", ((" to ",), (), False), ()),
    "hltl.grounding._normalise2:_kick_off35": (
        "090740f4ee8eb085",
        ((), (" with ",), True),
        (
            (
                "_KICK_OFF35",
                (
                    "pattern",
                    "^(?:kick off|lead off|open|get going|get started) with (?P<task>[^,.;!?]+?)(?P<sep>,?\\s+(?:and )?)(?:follow (?:up|on|that up|it up)|finish (?:off|up)|round (?:off|it off)) with (?P<next>[^,.;!?]+?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_kinds_named26s": (
        "723b8f57f0631497",
        ((), (" or ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise2:_left_it32": (
        "91561256c58348c7",
        ((), (" left ",), True),
        (
            (
                "_LEFT_IT32",
                (
                    "pattern",
                    "^(?P<who>somebody|someone|(?:the|our|my) [a-z]+) left (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?P<where>out|about|lying around|on the side|over there|here|there)\\s*[;,]\\s*(?:so\\s+)?(?P<v>[a-z]+) it\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_lent33": ("fa453ba3bcb78a1b", ((" lent ",), (), False), ()),
    "hltl.grounding._normalise2:_let_go26": (
        "0be285f68640718d",
        ((), (" the ", "leave "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_let_take30": ("dc541ccd775462b0", ((), (" if ",), False), ()),
    "hltl.grounding._normalise2:_like_a31": ("416a9269357c3390", ((), (" like ",), False), ()),
    "hltl.grounding._normalise2:_located26": (
        "f7eef0438b5f4fa2",
        ((), (" the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_made_it26": (
        "eb3d9463b12b3b04",
        ((), ("make ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_make_way31": ("a7c4e3e74d4f43f4", ((), ("way",), False), ()),
    "hltl.grounding._normalise2:_mid_aside34": ("5338068b8861685f", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_mind30": (
        "3231eda00b484d49",
        ((), ("mind ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_mind_if34": (
        "029040546b54a548",
        ((), ("mind if ",), True),
        (
            (
                "_MIND_IF34",
                (
                    "pattern",
                    "^(?:do you |would you )?mind if (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?P<v>grabs|takes|has|borrows|gets|nabs) (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?P<off> off you)?\\s*\\?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_more_than33": (
        "37f4ea0dc0d35650",
        ((" more than ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_my_hands33": ("13cca339bc231806", ((), ("my hands",), False), ()),
    "hltl.grounding._normalise2:_named_after30": (
        "99f5f1054861992e",
        ((), ("her", "him", "them"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise2:_needed_at35": ("9776f59b6ea83544", (("'s ",), (), False), ()),
    "hltl.grounding._normalise2:_needs_doing30": (
        "288ed343037cc42a",
        ((), ("need", "want"), False),
        (),
    ),
    "hltl.grounding._normalise2:_needs_most32": ("8ad501a9ebdb39d2", ((" is ",), (), False), ()),
    "hltl.grounding._normalise2:_negated_reason31s": (
        "bbe192a2ae79186d",
        (
            (),
            (
                "aren't",
                "can't",
                "didn't",
                "doesn't",
                "hasn't",
                "haven't",
                "isn't",
                "not",
                "wasn't",
                "won't",
                "wont",
            ),
            True,
        ),
        (
            (
                "_NOT_REASON31S",
                (
                    "pattern",
                    "\\s*,\\s*(?P<said>(?:(?:and|cos|because|as|since)\\s+)?(?:she|he|it|they|(?:the|her|his|their) [a-z]+)(?:'s| is| has)? ?(?:won't|wont|isn't|hasn't|can't|doesn't|didn't|haven't|aren't|wasn't|not|'s not|'re not| is not| has not)\\b[^,.;!?—–]*?)\\s*(?=[.!?]|$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_negation19": (
        "c21549dff76dba4f",
        ((), (" any", " save ", " that isn't ", "except ", "not ", "nothing ", "that"), True),
        (
            (
                "_nothing_for20",
                (
                    "guarded",
                    "hltl.grounding._normalise2:_nothing_for20",
                    "b7e337ff86bd6f7c",
                    (
                        (
                            "_sub",
                            ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77"),
                        ),
                    ),
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise2:_next30": ("9e62e08138fc8aff", ((), ("next",), False), ()),
    "hltl.grounding._normalise2:_not_had35": (
        "af865293fd0d9acf",
        ((), (" over",), True),
        (
            (
                "_NOT_HAD35",
                (
                    "pattern",
                    "^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:hasn't|has not|hasn't yet|has not yet) (?:had|got|been given|received) (?P<pron>his|her|their) (?P<x>[a-z]+(?: [a-z]+)?),\\s*(?P<v>take|bring|carry|pop) (?P<it>them|it) over\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_note_and30": ("99729c71911e2af9", ((":",), (), False), ()),
    "hltl.grounding._normalise2:_object_wants28": (
        "b0a9fcfce6f7ff92",
        ((), (" to ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise2:_off_the31": (
        "6775ccfdd242d541",
        ((), (" from ", " off ", " out "), False),
        (),
    ),
    "hltl.grounding._normalise2:_office35": (
        "a1d4df621a8f4799",
        ((), (" action ",), True),
        (
            (
                "_ACTION_DOING35",
                ("pattern", "\\b(?P<ask>can|could) (?:we|you) action (?P<v>[a-z]+)ing\\b", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_on_about33": (
        "5dfdb5fddba01b9d",
        ((" it",), ("on about",), True),
        (
            (
                "_ON_ABOUT33",
                (
                    "pattern",
                    "(?:\\s+has|'s) been (?:going )?on about\\b(?= (?:the|that|this|those|these)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_on_with35": ("a7f2bdabdc59a71a", ((" with ",), (), False), ()),
    "hltl.grounding._normalise2:_one_person22": (
        "8491882b840d10cc",
        ((), (" the ", "chef ", "doctor ", "mr ", "mrs ", "nurse "), False),
        (("_said_any", ("function", "hltl.grounding._normalise1:_said_any", "0b8ee6b8c4d04658")),),
    ),
    "hltl.grounding._normalise2:_one_task_two_sentences31": (
        "5788136c8c29cb97",
        ((".",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_over_and34": (
        "3e3b8d9982a90bdd",
        ((" over, and ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_over_to30": ("f4958b1fbbbdc1b3", ((), ("to ",), False), ()),
    "hltl.grounding._normalise2:_own_on33": ("e6eeed801a250a49", ((" in", " on"), (), False), ()),
    "hltl.grounding._normalise2:_path30": ("aa75616dbe2fb2bc", ((), (" the ",), False), ()),
    "hltl.grounding._normalise2:_possession32": (
        "217ecb0947ee11ac",
        ((" hers ", " his ", "'s"), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_purpose28": ("d6e701891f7e88fb", ((), ("for ",), False), ()),
    "hltl.grounding._normalise2:_questions26": (
        "4313f36eeaac91e7",
        ((), (" you ", "is it "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_questions34": (
        "58d38a1801fae29c",
        ((), (" about ", " you ", "see your way"), True),
        (
            (
                "_SEE_WAY34",
                (
                    "pattern",
                    "^(?P<ask>(?:could|can|would) you) (?:possibly )?see your way(?: clear)? to (?P<v>[a-z]+)ing\\b",
                    34,
                ),
            ),
            (
                "_THEN_ASKED34",
                (
                    "pattern",
                    "^(?P<q>(?:can|could|would|will) you [^,.;!?]+?),\\s*then\\s*\\?\\s*$",
                    34,
                ),
            ),
            (
                "_WOULD_WORK34",
                (
                    "pattern",
                    "^(?P<q>(?:what|how) about [a-z]+ing\\b[^,.;!?]*?),\\s*(?:would|does|will|is) that (?:work|do|be (?:okay|ok|alright|all right|possible|fine)|suit you)\\s*\\?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_questions35": (
        "b014a186c6016d27",
        (
            (),
            (
                "how does that sound",
                "is it ",
                "sound good",
                "sound ok",
                "what d'you reckon",
                "what d'you say",
                "what do you reckon",
                "what do you say",
                "what say you",
            ),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_SEND_OFF35",
                (
                    "pattern",
                    "\\bis it (?:alright|all right|ok|okay|fine) (?:to|if (?:i|we|you)) send (?P<p>her|him|them|[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:off|away|home) with (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?P<end>\\s*\\?)\\s*$",
                    34,
                ),
            ),
            (
                "_WHAT_SAY35",
                (
                    "pattern",
                    ",\\s*(?:what do you say|what d'you say|what say you|what do you reckon|what d'you reckon|how does that sound|sound good|sound ok|sound okay)\\s*\\?\\s*$",
                    34,
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_rather26": (
        "456eedcc861a7e53",
        ((), ("prefer", "rather have"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_reasons28": (
        "cecc25b225e5c0e7",
        (
            (),
            (
                " are",
                " had",
                " has",
                " have",
                " is",
                " was",
                " were",
                "'d",
                "'m",
                "'re",
                "'s",
                "'ve",
                "arrived",
                "began",
                "both",
                "broke",
                "came",
                "closed",
                "dragged",
                "ended",
                "fell",
                "finished",
                "got",
                "her",
                "his",
                "left",
                "my",
                "opened",
                "our",
                "ran",
                "started",
                "stopped",
                "the",
                "took",
                "went",
            ),
            True,
        ),
        (
            (
                "_REASON28",
                (
                    "pattern",
                    "(?:\\s*[,;]\\s*|\\s+[—–-]\\s+)((?:(?:oh|and|cos|coz|cause|because|as|since|seeing as|seeing that|given that|now that)\\s+)?(?:(?:they|we)(?:'re| are| were) (both)\\b|(?:her|his|their|my|our|the) (?!(?:and|or|the|a|an)\\b)[a-z-]+(?: (?!(?:and|or|the|a|an)\\b)[a-z-]+){1,2}(?:'s| is| are| was| were| has| have| had| keeps?)|(?:her|his|their|my|our|the) (?!(?:and|or|the|a|an)\\b)[a-z-]+(?: (?!(?:and|or|the|a|an)\\b)[a-z-]+){0,2} (?:ran|went|got|came|took|fell|broke|began|overran|finished|started|ended|arrived|left|stopped|closed|opened|dragged|ran over)|(?:she|he|it|they|we|i)(?:'s|'re|'ve|'d|'m| is| are| was| were| has| have| had) |(?:she|he|it|they|we|i) (?:ran|went|got|came|took|fell|broke|began|overran|finished|started|ended|arrived|left|stopped|closed|opened|dragged|ran over))\\b[^,.;!?—–]*?)\\s*(?=[.!?]|$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_restated26": (
        "f0978a380117197b",
        ((), ("the",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_run_on_close31": (
        "8384c2c1bed3981c",
        ((), ("that's ",), True),
        (
            (
                "_RUN_ON_CLOSE31",
                (
                    "pattern",
                    "(?:\\s*,)?\\s+(?:and )?(?:(?:right|okay|ok|so)\\s*,?\\s+)?(?:that's (?:it|all|everything)(?:,? that's (?:it|all|everything))*(?: from (?:the|your) (?P<trade>[a-z]+(?: [a-z]+)?))?|that's (?:the|our|my|them|the two of them|both of them) ?(?P<who>[a-z]*) (?:fed|sorted|done|happy|set|watered|looked after))(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_run_on_it30": ("081e4f891cf05fe0", ((), (" it ",), False), ()),
    "hltl.grounding._normalise2:_run_on_mid36": ("51f6316b44af54e6", ((" been ",), (), False), ()),
    "hltl.grounding._normalise2:_run_on_remark26": (
        "883611fc7531c489",
        ((), ("he",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise2:_run_on_remarks34": (
        "83f9dd19ee0272f1",
        ((), ("so",), True),
        (
            (
                "_RUN_ON_REMARKS34",
                (
                    "pattern",
                    "^(?P<said>(?:i|i'm|i've|i am|i have|we|we're|we've)\\b[^,.;:!?]*?)\\s+so\\s+(?=(?:could|can|would|will) you\\b|please\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_run_on_said32": (
        "7e8e5428ed68fc4f",
        ((" so",), ("then it's ",), True),
        (
            (
                "_BREAK32",
                (
                    "pattern",
                    ",?\\s+(?:and )?then it's (?:tea|coffee|lunch|dinner|home|my|our)(?: break| time)?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_safe_where31": (
        "749277996baf8d0b",
        (
            (),
            (
                "like",
                "little hands",
                "need",
                "no one",
                "no-one",
                "nobody",
                "the cat",
                "the children",
                "the dog",
                "the kids",
                "want",
            ),
            True,
        ),
        (
            (
                "_SAFE_WHERE31",
                (
                    "pattern",
                    ",\\s*(?:where|so) (?:nobody|no one|no-one|the kids|the children|little hands|the dog|the cat) (?:will|can|'ll|could|won't|can't)\\s+(?:knock|reach|get at|get to|grab|spill|break|touch)(?: (?:it|them))?(?: (?:over|down|off))?(?P<end>\\s*[.!]?)\\s*$|,\\s*(?:(?:the|our|my) (?P<trade>[a-z]+)|she|he|they|I|we) (?:wants?|likes?|would like|'d like|needs?) (?:it|them) (?:kept )?(?:out of reach|out of the way|up high|somewhere safe|safe)(?P<end2>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_same_again28": (
        "0a4eae64f19d3902",
        ((), ("same again",), False),
        (),
    ),
    "hltl.grounding._normalise2:_same_person29": ("ae42f7cb959700ac", ((), ("same",), False), ()),
    "hltl.grounding._normalise2:_same_person32": ("e5ce6003a64d0843", ((), ("same",), False), ()),
    "hltl.grounding._normalise2:_same_place26": (
        "bb384882fb34deaa",
        ((), ("same place",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise2:_sat_on35": (
        "e166b566efc6076e",
        ((" would ", "'d "), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_says29": ("ecd90c6eaac9cba6", ((), ("says",), False), ()),
    "hltl.grounding._normalise2:_says_in32": ("601c3ca208da276f", ((" say",), (), False), ()),
    "hltl.grounding._normalise2:_see_the29": (
        "8e282454efd4ae72",
        ((), ("see ",), True),
        (
            (
                "_SEE_THE29",
                (
                    "pattern",
                    "^(?:(?:do |can )?you )?see (the|that|this) ([a-z][a-z ]*?)\\?\\s*",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_see_the34": ("a67618a9611411f2", ((), ("see ",), False), ()),
    "hltl.grounding._normalise2:_serve_first31": (
        "7e3b0cd98019c0a3",
        ((), (" first,",), True),
        (
            (
                "_SERVE_FIRST31",
                (
                    "pattern",
                    "^(?:serve|see to|start with|begin with) (?P<p>[A-Za-z]+(?: [A-Za-z]+)?) first,\\s*(?P<v>give|hand|pass|bring) (?P<pron>her|him|them) (?=(?:the|that|this|those|these) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_set_out30": ("d604320174ae20ef", ((), (" out ",), False), ()),
    "hltl.grounding._normalise2:_since28": ("88e4070b22e05ecd", ((), ("since ",), False), ()),
    "hltl.grounding._normalise2:_since32": ("88994f65a4fed81e", (("since",), (), False), ()),
    "hltl.grounding._normalise2:_since_wanted34": (
        "c62e0510e12d367d",
        ((" since ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_size_words34": (
        "e372f8d29c7f46f8",
        ((), ("her", "his", "that", "the", "your"), True),
        (
            (
                "_SIZE_WORD34",
                (
                    "pattern",
                    "\\b(?P<det>the|that|this|your|her|his|their) (?P<size>wee|little|tiny|teeny|small|big|huge|massive|large) (?P<noun>[a-z]+)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_so_that30": ("42d671340c6e8a5f", ((), (" so ",), False), ()),
    "hltl.grounding._normalise2:_speaker_parts32": (
        "38b01f1e7628e90d",
        (
            (),
            (
                " think of it",
                " you get a ",
                " you go",
                " you manage ",
                "before i forget",
                "if you c",
                "in your own ",
                "suits",
                "while i remember",
            ),
            True,
        ),
        (
            (
                "_PARTS32",
                (
                    "pattern",
                    "(?:(?:oh,? )?and )?(?:before I forget|while I think of it|while I remember|(?:now|come to) think of it)|(?:just )?(?:whenever|when) (?:it )?suits(?: you)?|(?:whenever|when) you get a (?:chance|moment|minute|sec|second)|in your own (?:good )?time|(?:off|away|on) you go|(?:could|can|would) you manage (?:that|it)|if you (?:can|could) manage (?:it|that)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_speaker_parts33": (
        "6fb838e744d43d37",
        (
            (),
            (" as that", " in advance", " yes", "go on", "hurry", "nothing ", "quick one", "rush"),
            True,
        ),
        (
            (
                "_PARTS33",
                (
                    "pattern",
                    "(?:hello there|hello|hi),? nothing (?:fancy|special)(?: today| this time)?|(?:just )?(?:a )?quick one(?: before (?:the|my|our|his|her) [a-z]+(?: [a-z]+)?)?|nothing (?:fancy|special)(?: today| this time)?|(?:ah|oh|well),? go on(?:,)? then|go on(?:,)? then|(?:it's |that's |it is |that is )?(?:as )?(?:simple|easy) as that|(?:cheers|ta|thank you|thanks|many thanks) in advance|(?:and,? )?(?:oh|ah),? yes|(?:there's )?no (?:rush|hurry)(?: at all)? (?:on|with|for) (?:either|any|both|each|all|none)(?: one)?(?: of them| of the two| of those)?|(?:there's )?no (?:rush|hurry)(?: at all)? (?:on|with|for) (?:them|it)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_speaker_parts34": (
        "7cb84eba4ba08401",
        ((), (" urgently", "at all", "dear me", "hope ", "whatsoever"), True),
        (
            (
                "_PARTS34",
                (
                    "pattern",
                    "(?:i )?hope (?:the|your) (?:[a-z]+ ){0,2}[a-z]+ (?:was|is|has been|'s been) (?:kind|good|easy|gentle) (?:to|on) you|(?:i )?hope you(?:'re| are) (?:well|keeping well|doing well)|(?:there's )?no (?:rush|hurry)(?: at all| whatsoever)|(?:kind of|sort of|kinda|quite|rather|fairly|pretty|a bit) urgently|(?:oh )?dear me",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_start_with33": (
        "51da817f4ac0308c",
        ((), ("begin", "start"), False),
        (),
    ),
    "hltl.grounding._normalise2:_state_after30": (
        "e8a1af9518d32c69",
        ((), (" after ",), False),
        (),
    ),
    "hltl.grounding._normalise2:_state_and30": ("e342d9eba6b3c6dc", ((), (" and ",), False), ()),
    "hltl.grounding._normalise2:_state_it32": (
        "3060a31fe491181f",
        ((), (" it",), True),
        (
            (
                "_STATE_IT32",
                (
                    "pattern",
                    "^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:is|'s) (?:all |a bit |really |very |still |soaking )?(?P<state>[a-z]+)\\s*,\\s*(?:so\\s+)?(?P<v>[a-z]+) it\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_state_it35": (
        "b804ad7f8cd68b82",
        (
            (),
            (
                " the ",
                " way",
                "been knocked",
                "dropped",
                "fallen",
                "got knocked",
                "rolled",
                "slipped",
                "tipped",
                "under ",
            ),
            True,
        ),
        (
            (
                "_STATE_IT35",
                (
                    "pattern",
                    "^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?:'s|'re| is| are|'ve| has| have) (?:(?:fallen|dropped|rolled|tipped|slipped|been knocked|got knocked)(?: over| down| off)?(?: (?:on|onto) the (?:floor|ground|carpet|rug))?|in (?:the|my|our|your) way|(?:on|all over) the (?:floor|ground|carpet|rug)|under (?:my|our|your) feet),\\s*(?:so\\s+)?(?P<v>put|set|pop|place|stick|move|pick|lift|give|hand|take|bring|pass)(?P<up> up)? (?P<pron>it|them)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_state_so31": (
        "18bf19a031622659",
        ((), (" so ",), True),
        (
            (
                "_STATE_SO31",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z]+(?: [A-Za-z]+)?) (?P<be>is|'s) (?P<how>(?:really |very |so |a bit |dead )?[a-z]+) so (?=[a-z])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_stay28": ("8ce2ed401aae00b4", ((), ("stay",), False), ()),
    "hltl.grounding._normalise2:_stay_put36": (
        "a3c928643cd2e916",
        (("remain", "stay"), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_story32": (
        "1d9625b11ec0bb4e",
        (
            (),
            (
                "ate",
                "drank",
                "emptied",
                "finished",
                "nicked",
                "pinched",
                "polished off",
                "ran out of",
                "used",
            ),
            True,
        ),
        (
            (
                "_STORY32",
                (
                    "pattern",
                    ",\\s*(?P<who>(?:the|our|my|some) [a-z]+) (?:drank|ate|finished|used|emptied|nicked|pinched|polished off|ran out of) (?:all |up |off )?(?:of )?(?P<what>(?:the|our|my|their) [a-z]+)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_subject_comma26": (
        "dd25d6edbe27e32a",
        ((), ("the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_tag28": ("4e52be34a9b279f0", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_telegraph35": (
        "4f5a8023f6ede6d9",
        ((), ("th",), True),
        (
            (
                "_TELEGRAPH35",
                (
                    "pattern",
                    "^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)\\.\\s+(?P<for>for|to) (?P<p>[A-Z][A-Za-z]*(?: [A-Z][a-z]*)?)\\.(?=\\s|$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_thanks_from34": (
        "9c0ae6c6fbbb7f15",
        ((), (" from ",), True),
        (
            (
                "_THANKS_FROM34",
                (
                    "pattern",
                    ",\\s*(?:and\\s+)?(?:thanks|thank you|cheers|many thanks)(?: very much| a lot)? from (?:(?:the|our|my) (?P<trade>[a-z]+) and (?:me|us)|(?:me|us) and (?:the|our|my) (?P<trade2>[a-z]+))(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_the_moment31": (
        "6904e7d17a14e390",
        ((), ("as soon as", "the minute", "the moment", "the second"), True),
        (
            (
                "_THE_MOMENT31",
                (
                    "pattern",
                    "\\b(?:the moment|the minute|the second|as soon as) (?:you've|you have|you're|you are) (?:done|finished|through with) (?:that|it|this)(?: one)?,?\\s+(?=[a-z])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_then_after30": ("3c48555774bf0419", ((), ("after",), False), ()),
    "hltl.grounding._normalise2:_then_trade35": ("8ca2e08f0bbdec39", (("then ",), (), False), ()),
    "hltl.grounding._normalise2:_there_it33": ("1d0571fff257be4f", ((), ("there",), False), ()),
    "hltl.grounding._normalise2:_this_time26": (
        "02ce81f272f6a0d3",
        ((), ("this time",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise2:_those_are33": ("bbab6e8023069d0a", (("'s, so ",), (), False), ()),
    "hltl.grounding._normalise2:_till_got30": (
        "cb40b829564e6776",
        ((), ("till", "until"), False),
        (),
    ),
    "hltl.grounding._normalise2:_time_for36": (
        "1cbe0bb2ea799851",
        ((), (" so it", "for the "), True),
        (
            (
                "_FOR_THE_LAST36",
                (
                    "pattern",
                    "\\s+for the (?:first|last|next|early|late|morning|afternoon|evening|night) (?P<n>[a-z]+)(?: of the (?:day|night|week|shift|morning|afternoon|evening))?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_TIME_SO36",
                (
                    "pattern",
                    "^(?P<what>[a-z]+) (?:time|o'clock|oclock),? so (?:it's|its|it is) ",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_to_do31": ("567d878bed5a169e", ((), (" to ",), False), ()),
    "hltl.grounding._normalise2:_to_do34": ("445fd33f47425e84", ((" to ",), (), False), ()),
    "hltl.grounding._normalise2:_to_do_with32": ("f50ed4ec3d17c89a", ((" to ",), (), False), ()),
    "hltl.grounding._normalise2:_told_me31": (
        "daee5c8a97786f10",
        ((), ("tell", "told"), True),
        (
            (
                "_TOLD_ME31",
                (
                    "pattern",
                    ",\\s*(?:or so )?(?:(?:she|he|they) (?:tells|told|has told|'s told|tell|have told|'ve told) me|I'm told|I am told|I've been told|I was told)(?:\\s+(?:so|earlier|just now))?(?P<end>\\s*[.!]?\\s*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_too_warm32": (
        "78b1539667b97074",
        ((), (" are", " is", "'re", "'s"), True),
        (
            (
                "_TOO_WARM32",
                (
                    "pattern",
                    ",\\s*(?:(?:the|it's|it is) )?(?P<what>[a-z]+)(?:'s| is| are|'re) (?:too|so|really|very|ever so|a bit|far too|way too) (?P<state>[a-z]+)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_trade_on31": (
        "0aaae71d5c3c0eed",
        ((), (" is ", "'s "), False),
        (),
    ),
    "hltl.grounding._normalise2:_trade_said36": (
        "92244f96a7bebaf4",
        (
            ("the ",),
            (" at ", " first with ", "afterwards", "in a bit", "later", "likes", "prefers"),
            True,
        ),
        (
            (
                "_FINISHES_AT36",
                (
                    "pattern",
                    ",\\s*(?P<what>[a-z]+) (?:finishes|ends|starts|kicks off|is over) at (?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|[0-9]{1,2})(?: o'clock| oclock| ?[ap]m)?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_FIRST_WITH36",
                (
                    "pattern",
                    "^(?P<p>(?:person [a-z]|[a-z]+)) first with (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?= and (?:after that|then)\\b|,? then\\b)",
                    34,
                ),
            ),
            (
                "_TRADE_COMPOUND36",
                (
                    "pattern",
                    "(?P<p>\\b(?:Person [A-Z]|[A-Z][a-z]+(?: [A-Z][a-z]+)?)),\\s*the (?P<w1>[a-z]+) (?P<w2>[a-z]+(?:er|or|ist|man|woman|keeper|hand|maker))(?=\\s*(?:[,.;!?]|$))",
                    32,
                ),
            ),
            (
                "_TRADE_REMARK36",
                (
                    "pattern",
                    ",\\s*(?:the|our|my) (?P<trade>[a-z]+) (?:(?:likes|prefers|likes to have|likes to keep) (?:things|everything|it all|stuff) (?:stowed|tidy|neat|put away|shipshape|in order|just so|squared away|off the floor)|(?:will|'ll|is going to) (?:eat|snack|have a snack|have lunch|have tea|have supper) (?:later|in a bit|afterwards))(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_trade_says33": ("bb3268e4a62c2fd2", ((" says",), (), False), ()),
    "hltl.grounding._normalise2:_trade_wants31": (
        "221d4c76d1fb1dbc",
        ((), ("asked for", "is after", "needs", "wants", "would like"), True),
        (
            (
                "_TRADE_WANTS31",
                (
                    "pattern",
                    ",\\s*(?:the|our|my|your) (?P<trade>[a-z]+(?: [a-z]+)?) (?:wants|needs|has asked for|asked for|would like|is after) (?:it|them|those|that|both)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_trades31": ("d9118d4503c0654c", ((",",), (), False), ()),
    "hltl.grounding._normalise2:_translated25": (
        "9a1f4fb92200164a",
        (
            ("ak", "as", "u"),
            (
                " rog",
                "alsjeblieft",
                "alstublieft",
                "bebakhsheed",
                "bebakhshid",
                "bebakhshin",
                "bitte",
                "dat",
                "di",
                "dzu",
                "ebakachihu",
                "ebakih",
                "ebakish",
                "fi",
                "gtkhovt",
                "jus",
                "karunakarala",
                "kripya",
                "lotfan",
                "maaf",
                "mek",
                "mesedez",
                "mi mean",
                "molim",
                "nuh",
                "onegaishimasu",
                "palun",
                "parakalo",
                "per favore",
                "pon",
                "por favor",
                "pozhaluista",
                "pozhaluysta",
                "pra",
                "pros",
                "s'il vous pla",
                "si us plau",
                "sil vous plait",
                "tafadhali",
                "tfen",
                "tolong",
                "wid",
            ),
            True,
        ),
        (
            (
                "_HONORIFIC25",
                ("pattern", "\\b(?:[Bb]u|[Ii]bu|[Pp]ak|[Bb]apak|[Mm]as|[Mm]bak)\\s+(?=[A-Z])", 32),
            ),
            (
                "_PATOIS_WORD25",
                (
                    "pattern",
                    "\\b(?:di|dat|dis|fi mi|fi|jus|mek|pon|wid|mi mean|nuh matter)\\b(?=[\\s',.;!?]|$)|\\s*\\bnuh\\b(?=\\s*[,.;!?])",
                    34,
                ),
            ),
            (
                "_PLEASE25",
                (
                    "pattern",
                    "\\b(?:bisa tolong|tolong|lotfan|bitte|por favor|prosím|prosim|vă rog|va rog|prašau|prasau|prašom|prasom|gtkhovt|ebakih|ebakish|ebakachihu|karunakarala|lūdzu|ludzu|palun|proszę|prosze|molim|alstublieft|alsjeblieft|lütfen|lutfen|pozhaluysta|pozhaluista|parakalo|tafadhali|kripya|s'il vous pla[iî]t|sil vous plait|per favore|onegaishimasu|si us plau|mesedez)(?!\\w)",
                    34,
                ),
            ),
            ("_SORRY25", ("pattern", "\\b(?:bebakhshid|bebakhshin|bebakhsheed|maaf)\\b", 34)),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_up_on31": ("efb5be3d96628325", ((), (" in", " on"), False), ()),
    "hltl.grounding._normalise2:_verb_last34": (
        "74178e2a1299fd0e",
        (("bring", "give", "hand", "pass"), (), True),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise2:_want_idioms35": (
        "46c47f68890aeee0",
        ((" without ",), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_want_run_on35": (
        "3052fb61390eeec6",
        ((), ("'s after", "for ", "is after", "needs", "wants"), True),
        (
            (
                "_WANT_RUN_ON35",
                (
                    "pattern",
                    "^(?P<want>(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)(?:'s| is) (?:meant |intended )?for (?P<p>person [a-z]|[a-z]+)|(?P<q>person [a-z]|[a-z]+) (?:is after|'s after|wants|needs) (?P<y>(?:the|her|his|their) [a-z]+(?: [a-z]+)?)) (?P<then>so|can you|could you|would you)\\b",
                    34,
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise2:_wants_said36": (
        "b0ee35a8a020026d",
        ((), (" been ", " out", " out,", "is where "), True),
        (
            (
                "_ASKED_BY36",
                (
                    "pattern",
                    "^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?:'s| has|'ve| have) been (?:asked for|requested|ordered|bagged|claimed|put aside) by (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?P<aside>,\\s*who [^,]+,)?",
                    34,
                ),
            ),
            (
                "_LEFT_OUT36",
                (
                    "pattern",
                    "(?P<lead>,\\s*)(?:the|our|my) (?P<trade>[a-z]+) (?:left|got|took|has left|'s left) (?P<pron>it|them) out(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_LEFT_X_OUT36",
                (
                    "pattern",
                    "^(?:the|our|my) (?P<trade>[a-z]+) (?:left|got|took|has left|'s left) (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) out,\\s*so (?P<req>.+)$",
                    34,
                ),
            ),
            (
                "_WHERE_OUGHT36",
                (
                    "pattern",
                    "\\bis where (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:ought to|has to|must|wants to) (?P<v>be|go)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_what_like34": (
        "936a3624588e8ac1",
        ((), ("what ",), True),
        (
            (
                "_WHAT_LIKE34",
                (
                    "pattern",
                    "^what (?P<who>i'd|i would|we'd|we would) (?P<v>like|love|want) is (?=(?:the|that|this|those|these)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_what_needs31": (
        "633c5fa7b3bb713a",
        ((), ("what ",), True),
        (
            (
                "_WHAT_NEEDS31",
                (
                    "pattern",
                    "^what (?P<p>[A-Za-z]+(?: [A-Za-z]+)??) (?:really |most )?(?P<v>needs|wants|would like)(?: (?:right now|now|most))?,\\s*(?P<why>(?:after|since) (?:his|her|their|a|the) [^,]+?),\\s*is (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_what_waiting34": (
        "84cc764273d923fc",
        (("what ",), ("over to ",), True),
        (
            (
                "_OVER_WITH34",
                (
                    "pattern",
                    "\\b(?P<so>so |and )?over to (?P<who>her|him|them) with (?P<x>it|them)(?=\\s*[.!]?\\s*$)",
                    34,
                ),
            ),
            (
                "_WHAT_WAITING34",
                (
                    "pattern",
                    "^(?P<x>(?:[Tt]he|[Tt]hat|[Tt]his|[Tt]hose|[Tt]hese) [a-z][a-z ]*?) (?:is|are|'s) (?:just )?what (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?P<v>(?:'s| has) been (?:waiting (?:on|for)|after|asking for|wanting)|(?:'s| is) (?:waiting (?:on|for)|after)| wants| needs| asked for)(?=\\s*[,.;!?]|\\s+(?:and|so)\\b|\\s*$)",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_where_goes35": ("75cb0111680dd3f3", ((" where ",), (), False), ()),
    "hltl.grounding._normalise2:_where_she_is34": (
        "adf030300b6bbaee",
        ((" is ", "'s "), (), False),
        (),
    ),
    "hltl.grounding._normalise2:_while26": (
        "7121a8fec33b07e7",
        ((), ("while ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise2:_while29": (
        "9e54a1a908a5d004",
        ((), (" after ", " while "), False),
        (),
    ),
    "hltl.grounding._normalise2:_while31": ("761a6a90d3944313", ((), (" while ",), False), ()),
    "hltl.grounding._normalise2:_while_go30": ("39cad0bd92e99148", ((), ("while",), False), ()),
    "hltl.grounding._normalise2:_who_is30": ("e9890f1e282f57ea", ((), (" and ",), False), ()),
    "hltl.grounding._normalise2:_who_she_is35": (
        "8b7eabbbbbd17ad9",
        ((), (" having a ", " take ", "but "), True),
        (
            (
                "_CAN_P_TAKE35",
                (
                    "pattern",
                    "^(?P<ask>can|could|may) (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) take (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)\\s*\\?\\s*$",
                    34,
                ),
            ),
            (
                "_HAVING_A35",
                (
                    "pattern",
                    ",\\s*(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| is) having a (?:tidy-up|tidy up|tidy|clear-out|clear out|sort-out|sort out|break|nap|lie-down|lie down|rest|day off)(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
            (
                "_JUST_A35",
                (
                    "pattern",
                    "^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| is) (?:just|only|merely) an? (?P<role>[a-z]+),?\\s+but (?P<ask>can|could|may) (?P<pron>she|he) (?P<rest>have|get|take) ",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_who_thats33": ("eaac3d878e40bb87", (("that's",), (), False), ()),
    "hltl.grounding._normalise2:_who_where28": (
        "d23cda141e66bf5b",
        ((), (" here", "at", "by", "from", "in", "my", "near", "on", "our", "the"), True),
        (
            (
                "_ROLE_FIRST28",
                ("pattern", "^(?:the|our|my|your) ([a-z]+(?: [a-z]+)?),\\s+([^,]+?),\\s+", 34),
            ),
            (
                "_WHERE_AFTER28",
                (
                    "pattern",
                    "^([^,]+?),\\s+((?:up|down|over|out|back|round)?\\s*(?:at|in|on|by|near|from) (?:the|a|an|his|her|their|my|our) [a-z]+(?: [a-z]+){0,2}),\\s+(?=[a-z])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_whose_take33": ("3f61fdd6749902cb", ((), ("that",), False), ()),
    "hltl.grounding._normalise2:_why_placed36": (
        "23fd8c6693b91109",
        ((), (" one", " with the other", "-one", "body"), True),
        (
            (
                "_SO_NOBODY36",
                (
                    "pattern",
                    "(?:,\\s*|\\s+)so (?:that )?(?:nobody|no one|no-one) (?:sits|steps|treads|stands|trips|kneels|leans|sits down|knocks|falls) (?:on|over|in|onto) (?P<pron>it|them)(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
            (
                "_WITH_OTHERS36",
                (
                    "pattern",
                    "(?P<place>\\b(?:on|onto|in|into) (?P<s>the [a-z]+(?: [a-z]+)?)) with the (?:others|other ones)(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise2:_will_do30": ("4d1bda72bc30b848", ((), (" do",), False), ()),
    "hltl.grounding._normalise2:_will_take31": ("ebca00d96302f330", ((), ("take",), False), ()),
    "hltl.grounding._normalise2:_with_going31": ("7f98a38471900a89", ((), (" with ",), False), ()),
    "hltl.grounding._normalise2:_with_her35": ("089eb9ec54beb9b1", ((" having ",), (), False), ()),
    "hltl.grounding._normalise2:_with_object31": ("44b4bdd1366bd736", ((), (" with ",), False), ()),
    "hltl.grounding._normalise2:_would_help33": ("a0dc0526089d2952", ((" help ",), (), False), ()),
    "hltl.grounding._normalise3:_alike31r": (
        "e3e7f61dda7cc979",
        ((), ("alike", "both", "the pair of them"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_all_kit29r": (
        "abf45024587175ff",
        ((), (" all the ",), True),
        (
            (
                "_ALL_KIT29R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?P<v>wants|needs|gets|should get|can have) all the (?P<w>[a-z]+) (?:except|but|apart from|bar) (?P<x>[^:,]+?)\\s*[:,]\\s*(?:that's|that is|i\\.e\\.,?|namely|meaning)\\s+(?P<list>[^.!?]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_all_of27r": (
        "74be94eed5769f25",
        ((), (" of the",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_all_said29r": (
        "0f4e3b51004c7cb1",
        ((), ("welcome", "whatever"), True),
        (
            (
                "_WHATEVER_THERE29R",
                (
                    "pattern",
                    "^(?P<ex>(?:apart from|except(?: for)?|other than|besides|bar) [^,]+,\\s*[^,]*?)\\bwhatever(?:'s| is) (?:there|left|going|on offer)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_along_with28s": (
        "981822fed5a947af",
        ((), (" together", " with "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_and_leave30r": (
        "4c485d1c15bf253b",
        ((), ("leave ",), True),
        (
            (
                "_AND_LEAVE30R",
                (
                    "pattern",
                    ",\\s*and (?P<x>(?:the )?[a-z]+(?: [a-z]+)??),\\s*(?:no|oh no|wait|actually),\\s*leave (?P<y>(?:the )?[a-z]+(?: [a-z]+)??)(?: (?:be|alone|there|where it is|out))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_any_except32r": (
        "53fee2e40d8bf2b9",
        ((), ("any ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_apiece30r": (
        "ae90f2995535a893",
        ((), (" taking ",), True),
        (
            (
                "_APIECE30R",
                (
                    "pattern",
                    "^(?P<who>(?:the )?[a-z]+|they|the two of them|both of them) (?:get|gets|have|are getting) one (?:thing |item )?(?:apiece|each),\\s*(?P<p>[A-Za-z][\\w ]*?) taking (?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_apposed_list32r": (
        "cb5784f87b66e6f8",
        ((), ("the ",), True),
        (
            (
                "_APPOSED_LIST32R",
                (
                    "pattern",
                    "\\bthe (?P<n>two|three|four|five|six|2|3|4|5|6) (?:things|items|objects|bits)(?P<desc>(?: [a-z]+){1,4}?)?,\\s*(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\\s*|,? and )(?:the |a |an )?[a-z]+(?: [a-z]+)?)+)(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_bare_adjective31r": (
        "ffe9a61755c53635",
        ((), (" not ", "make "), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_beg_pardon30r": (
        "a8e3cdceab212683",
        ((), ("pardon",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_better_home31r": (
        "d17089ff1e16d1b4",
        ((), ("better",), True),
        (
            (
                "_BETTER_HOME31R",
                (
                    "pattern",
                    "(?P<cue>,\\s*(?:(?:oh|ah),?\\s*)?(?:hold on|hang on|wait|no|actually|on second thoughts?)(?:,?\\s*(?:no|actually))?,?\\s*)(?:(?P<s>the [a-z]+(?: [a-z]+)?)(?:'s| is|'d be| would be) (?:a |the )?better (?:home|place|spot|bet|choice)(?: for (?:it|them))?|better(?: off)?(?: down| up)? (?P<on>on|in|onto|into) (?P<s2>the [a-z]+(?: [a-z]+)?))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_both_for27r": ("f7eb87946908f80b", ((), ("both",), False), ()),
    "hltl.grounding._normalise3:_both_named33t": (
        "f9c1b3f4cd49982d",
        ((), (" does it", " they ", "both "), True),
        (
            ("_drop", ("function", "hltl.grounding._normalise1:_drop", "8cf37521cc8fd8a7")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_both_remark28r": ("a62d6ed218b69ef3", ((), ("both",), False), ()),
    "hltl.grounding._normalise3:_both_want_either32r": (
        "001de7f733ef5e62",
        ((), (" to either",), True),
        (
            (
                "_BOTH_WANT_EITHER32R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) and (?P<q>[A-Za-z][\\w ]*?) (?:both )?(?:want|need|would like|are after)(?: both)? (?P<x>the [a-z ]+?)\\s*[;,.:]\\s*(?:so )?(?:just )?(?:give|hand|pass) (?:it|them) to either(?: one)?(?: of them)?(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_busy_with28s": (
        "473b000388f1d387",
        ((), ("ing",), True),
        (
            ("_PERSON28S", ("value", "'person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+'")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_but_only_one30r": (
        "39a9260c2a3bd1ff",
        ((), ("just", "only"), True),
        (
            (
                "_BUT_ONLY_ONE30R",
                ("pattern", ",\\s*(?:but )?(?:only|just) (?:the )?one(?P<end>\\s*[.!]?)$", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_by_mistake31r": (
        "24e49185cd2375a4",
        ((), ("do not", "don't", "never"), True),
        (
            (
                "_BY_MISTAKE31R",
                (
                    "pattern",
                    "^(?P<req>[^;.!?]+?)\\s*(?P<mark>[;.]|,\\s*(?:but|and|so)?)\\s*(?P<neg>(?:but |and |so |just )?(?:don't|do not|never) (?:give|hand|pass|bring|take|send|put|place) )(?P<it>it|them) (?P<to>(?:to|on|onto|in|into) [^,;.!?]+?)(?: by (?:mistake|accident)| in error)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_cant_stand31r": (
        "51f795a21a4e8807",
        ((), ("not the ",), True),
        (
            (
                "_CANT_STAND31R",
                (
                    "pattern",
                    "(?P<keep>\\bnot the (?P<a>[a-z]+) (?:one|[a-z]+)),\\s*(?:(?:he|she|they|i|we)(?: just)? (?:can't stand|cannot stand|can't abide|can't bear|hates?|dislikes?|doesn't like|don't like|isn't keen on|aren't keen on|is not keen on|won't have|doesn't want|don't want)) (?P<b>[a-z]+)(?: ones?| things?)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_choice_adjectives32r": (
        "d020c8ee6b5f2ffb",
        ((), (" of the ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_choice_said29r": (
        "39d6102a21fa6508",
        ((), (" of them,", " only ", "any "), True),
        (
            (
                "_ANY_ONE29R",
                (
                    "pattern",
                    "\\bany (?:one |single )?(?P<kind>[a-z]+),\\s*(?P<list>(?:the |a |an )?[a-z ]+? or (?:the |a |an )?[a-z ]+?)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
            (
                "_ONE_OF_THEM29R",
                (
                    "pattern",
                    "\\b(?:one|either) of them,\\s*(?P<list>(?:the |a |an )?[a-z ]+? or (?:the |a |an )?[a-z ]+?)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
            (
                "_only_needs29r",
                (
                    "guarded",
                    "hltl.grounding._normalise3:_only_needs29r",
                    "70cb930bff670932",
                    (
                        (
                            "_ONLY_NEEDS29R",
                            (
                                "pattern",
                                "^(?P<p>[A-Za-z][\\w ]*?) only (?P<v>needs|wants|requires|would like|asked for)\\b",
                                34,
                            ),
                        ),
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_choice_tail29r": (
        "3590543a7f093d36",
        ((), ("whichever",), False),
        (
            (
                "_CHOICE_TAIL29R",
                (
                    "pattern",
                    "\\s*[,;]\\s*(?:(?:just |so )?(?:pick|take|grab|choose|use) )?whichever(?: one)?(?:'s| is)? (?:comes to hand|you can reach(?: first)?|you reach first|is nearer(?: to you)?|is closer|is easier to reach|you can get to|you get to first)(?=\\s*(?:[,.!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_choice_tail32r": (
        "4f2afcfd097add40",
        ((), ("as long as it's ", "whichever"), True),
        (
            (
                "_CHOICE_TAIL32R",
                (
                    "pattern",
                    ",\\s*(?:whichever(?: one)?(?:'s| is) (?P<state>clean|free|handy|handier|nearer|closer|nearest|closest|dry|empty|spare)|(?:she|he|they)(?:'ll| will) (?:chew|use|take|have|like|play with|enjoy|be happy with) whichever(?: one)? you (?:hand|give|bring|pass) (?:her|him|them)|as long as it's (?:clean|dry|empty|not broken))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_cleft29r": (
        "10f688195f0b9fa4",
        ((), ("asked for", "meant", "needed", "needs", "ordered", "said", "wanted", "wants"), True),
        (
            (
                "_CLEFT29R",
                (
                    "pattern",
                    "(?P<cue>,\\s*no,)\\s*(?:(?:that's|that is|i got that|i had that) wrong,\\s*)?(?:it's|it is|it was) (?P<said>(?:the|that) [a-z ]+?) (?:asked for|wants|wanted|needs|needed|ordered|meant|said)\\s*(?=[.!]?$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_cleft_not29r": (
        "303b7e24cc55332a",
        ((), ("asked for", "needs", "wants", "would like"), True),
        (
            (
                "_CLEFT_NOT29R",
                (
                    "pattern",
                    "^it(?:'s| is) (?P<said>the [a-z ]+?) (?P<v>wants|needs|asked for|would like)(?: for (?P<why>[a-z' ]+?))?,\\s*not (?P<y>the [a-z ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_corrected_reason32r": (
        "6fd37e89083f9bf7",
        (
            (),
            (
                " got a ",
                " off ",
                " own",
                "break",
                "broken",
                "busy",
                "chipped",
                "cluttered",
                "cracked",
                "dirty",
                "empty",
                "filthy",
                "full",
                "hers",
                "his",
                "in use",
                "it already",
                "just",
                "leaking",
                "not here",
                "off shift",
                "one",
                "only",
                "sticky",
                "taken",
                "theirs",
                "wet",
            ),
            True,
        ),
        (
            (
                "_CORRECTED_REASON32R",
                (
                    "pattern",
                    "^(?P<head>.+?,\\s*(?:no|sorry|oops|hang on|wait|i mean|make it)\\b.+?),\\s*(?P<who>(?:the )?[A-Za-z][\\w ]*?)(?P<why>(?:'s| has) (?:got |already got |already had |had )?(?:one|(?:his|her|their) own|his|hers|theirs|one already|it already)(?: already)?|(?:'s| is) off (?:the )?[a-z]+|(?:'s| has) gone (?:on (?:a )?break|home|out|off shift)|(?:'s| is) (?:on (?:a )?break|not here|off shift|busy)|(?:'s| has) got a (?:crack|chip|hole|stain)(?: in it)?|(?:'s| is) (?:cracked|chipped|broken|dirty|filthy|empty|wet|leaking|sticky)|(?:'s| is) (?:wet|full|dirty|cluttered|taken|sticky|in use)|(?:'s| is) (?:only|just) (?:for|meant for) [a-z]+s)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_count_after31r": (
        "13c38441e8226553",
        ((), ("items", "objects", "things"), True),
        (
            (
                "_COUNT_AFTER31R",
                (
                    "pattern",
                    "(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\\s*|,? and )(?:the |a |an )?[a-z]+(?: [a-z]+)?)+),\\s*(?:that's |so )?(?P<n>two|three|four|five|six|2|3|4|5|6) (?:things|items|objects)(?: in all| altogether| in total)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_count_again28r": (
        "51391ac1438eae72",
        ((), ("all ",), False),
        (
            (
                "_COUNT_AGAIN28R",
                (
                    "pattern",
                    "\\s*,\\s*(?:that's |that is |so )?all (?P<n>two|three|four|five|six) (?:bits|things|items|pieces|objects|of them|of those)\\s*,\\s*",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_count_for29r": (
        "4e0d4d36eecd0d29",
        ((), (" for ",), True),
        (
            (
                "_COUNT_FOR29R",
                (
                    "pattern",
                    "^(?P<head>(?:one|two|three|four|five|six) (?:things?|items?) for [A-Za-z][\\w ]*?) to (?:take|carry|bring|have|use)(?: (?:them |it )?(?:to|for|with|along|back|home|away)(?P<why>[a-z' ]*))?\\s*:",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_counted_close33t": (
        "7b4ab16820a5436e",
        ((), ("five", "four", "one", "six", "three", "two"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_counted_header32r": (
        "1f4c6fde50620ecf",
        ((), ("s,",), True),
        (
            (
                "_COUNTED_HEADER32R",
                (
                    "pattern",
                    "^(?P<n>two|three|four|five|six|2|3|4|5|6) (?P<role>[a-z]+)s,\\s*(?P<m>two|three|four|five|six|2|3|4|5|6) (?P<kind>[a-z]+)s\\s*:\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_counted_those34t": (
        "6f5ef768463e3e22",
        ((), ("drop all ", "those "), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_couple_of31r": (
        "0c8606d29a6ea2a7",
        ((), ("a couple of ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_cue_reason28r": (
        "fc6d21f0e94c08e5",
        (
            (),
            (
                " no",
                " that",
                "cancel",
                "correction",
                "hang on",
                "hold on",
                "i mean",
                "i misspeak",
                "i misspoke",
                "let me rephrase",
                "my ",
                "nay",
                "oops",
                "pardon me",
                "rather",
                "revert",
                "rry",
                "scratch",
                "strike",
                "wait",
            ),
            True,
        ),
        (
            (
                "_CUE_REASON28R",
                (
                    "pattern",
                    "(?<=,)\\s*(?:(?:(?:no,? |(?:eh|ah),? no,? |(?:oh|eh|ah),? )?(?:sorry|so sorry)(?:,? (?:no|wrong))?(?:,? i meant?)?|whoops|oops|(?:no,? )?my (?:mistake|bad)|pardon me|i meant?|i misspeak|i misspoke|let me rephrase|(?:or )?rather|(?:no,? )?(?:strike|scratch|belay|revert|cancel) that(?: order)?|(?:wait|no wait|no),? (?:revert|scratch|strike|cancel) that|correction|no,? (?:wait|hold on|hang on)|(?:eh|ah),? no|nay(?:,? i misspeak)?|no,? sorry|no,? no))\\s*,\\s*(?P<why>[^,.;:!?]+?)\\s*,\\s*(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_cue_reason29r": (
        "33344eac89114573",
        (
            (),
            (
                " that",
                "cancel",
                "correction",
                "hang on",
                "hold on",
                "i mean",
                "i misspeak",
                "i misspoke",
                "let me rephrase",
                "my ",
                "nay",
                "no",
                "oops",
                "pardon me",
                "rather",
                "revert",
                "rry",
                "scratch",
                "strike",
                "wait",
            ),
            True,
        ),
        (
            (
                "_CUE_REASON29R",
                (
                    "pattern",
                    "(?:(?<=,)|(?<=[.!?]))\\s*(?P<cue>(?:(?:no,? |(?:eh|ah),? no,? |(?:oh|eh|ah),? )?(?:sorry|so sorry)(?:,? (?:no|wrong))?(?:,? i meant?)?|whoops|oops|(?:no,? )?my (?:mistake|bad)|pardon me|i meant?|i misspeak|i misspoke|let me rephrase|(?:or )?rather|(?:no,? )?(?:strike|scratch|belay|revert|cancel) that(?: order)?|(?:wait|no wait|no),? (?:revert|scratch|strike|cancel) that|correction|no,? (?:wait|hold on|hang on)|(?:eh|ah),? no|nay(?:,? i misspeak)?|no,? sorry|no,? no)|(?:(?:wait|hang on|hold on),? )?no)\\s*,\\s*(?P<why>[^,.;:!?]+?)\\s*[,;]\\s*(?P<so>so,?\\s+)?(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_dash_header31r": (
        "1a9389ba6f562498",
        ((), ("items", "objects", "things"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_described_list27": (
        "1858c19865392867",
        ((), ("both", "five", "four", "six", "that", "three", "two"), False),
        (),
    ),
    "hltl.grounding._normalise3:_did_i_say30r": (
        "afadc1348ca2f21b",
        ((), ("did i say ",), True),
        (
            (
                "_DID_I_SAY30R",
                (
                    "pattern",
                    "\\s*[;,.]\\s*(?:sorry|oops|whoops),?\\s*did i say (?P<a>[a-z' ]+?)\\?\\s*(?P<b>[A-Za-z' ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_dislocated28s": (
        "f36ad3861cde11c5",
        ((), ("the ",), True),
        (
            ("_PERSON28S", ("value", "'person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+'")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_disturb28s": (
        "396453c2236547db",
        ((), ("sorry",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_doesnt_want_just31r": (
        "0d991734a541ba54",
        ((), ("the ",), True),
        (
            (
                "_DOESNT_WANT_JUST31R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?:doesn't|does not|don't|do not) (?:want|need) (?P<x>the [a-z]+(?: [a-z]+)?)\\s*[,;]\\s*(?:just|only|but|she wants|he wants|they want) (?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_dont_suppose32r": (
        "ab416d2971e36add",
        ((), ("don't suppose ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_each_any33t": (
        "fc4e0c4f5b184e6b",
        ((), ("each of ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_each_for29r": (
        "ad73eaeb045a967b",
        ((), ("a thing", "an item", "one item", "one thing", "something"), True),
        (
            (
                "_EACH_FOR29R",
                (
                    "pattern",
                    "^(?:something|one thing|a thing|an item|one item) (?:each|apiece) for (?:the (?P<n>two|three) [a-z]+s|them|the (?P<m>two|three) of them|both of them)\\s*:\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_each_of_n29r": (
        "0709016faae87b10",
        ((), (" for each of the ",), True),
        (
            (
                "_EACH_OF_N29R",
                (
                    "pattern",
                    "\\b(?P<one>one|an?) (?P<x>[a-z]+) for each of the (?P<n>two|three) (?P<role>[a-z]+)s(?P<way>,\\s*(?:whichever|either|any) way round)?(?=\\s*[.!]?$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_each_one28r": (
        "dc67bee53618034a",
        ((), ("a thing", "both of ", "one "), True),
        (
            (
                "_EACH_ONE28R",
                (
                    "pattern",
                    "^(?:(?:so|now|right),? )?(?:(?:hand|give|share|dish) out )?(?:one (?:thing|item)|a thing) (?:each|apiece)\\s*[:,-]\\s*|^both of (?:them|you) (?:need|want|get|are after) (?:something|a thing|one thing)(?: each)?\\s*,\\s*so\\s+",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_each_role30r": (
        "b6696db9c8a52fde",
        ((), (" each ",), True),
        (
            (
                "_EACH_ROLE30R",
                (
                    "pattern",
                    "^(?:please,? )?(?P<what>one of the [a-z]+s|(?:one|an?) [a-z]+) (?:to|for) each (?P<role>[a-z]+)(?:,\\s*(?:whichever|either|any) way(?: round)?)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_each_said33t": (
        "6bba31fa175295c7",
        ((), ("and not ", "each "), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_either_title28r": (
        "c346e3486a449564",
        ((), ("any one of the", "either"), False),
        (),
    ),
    "hltl.grounding._normalise3:_er_person32r": (
        "eb072f8c347a2b4b",
        ((), ("person", "the only "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_every_last30r": (
        "91314e952a334cd8",
        ((), ("one of ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_every_one_of_them31r": (
        "f6a97d67c711d858",
        (
            (),
            (
                "all of them",
                "each and every one",
                "one of them",
                "the lot of them",
                "the whole lot",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_everything26s": (
        "3891a3867c0850be",
        ((), (" of the ", "clear ", "everything ", "leave ", "the "), True),
        (
            (
                "_EXCEPT26S",
                ("value", "'(?:except(?: for)?|bar|but(?: not)?|apart from|other than|not)'"),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_except_stays32r": (
        "164f18a08fb92875",
        ((), ("can stay", "is staying", "is to stay", "stays"), True),
        (
            (
                "_EXCEPT_STAYS32R",
                (
                    "pattern",
                    "(?P<head>\\b(?:except|apart from|other than|bar|but not) (?:for )?the [a-z ]+?)\\s*,\\s*(?:that|it|which)(?: one)? (?:stays|can stay|is staying|is to stay) (?:put|where it is|here|there)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_exclaimed_fix33t": (
        "e45815da6063eb92",
        ((), ("actually", "hang", "mean", "no", "oops", "sorry", "wait"), False),
        (),
    ),
    "hltl.grounding._normalise3:_fine_by_me31r": (
        "0c115310402883ed",
        ((), ("any", "both", "either", "whichever"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_for_table32r": (
        "6378481a9fb2a769",
        ((), ("for ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_formal33t": (
        "75125c9ac7daa101",
        ((), ("is it ", "no further questions", "respect,", "would it be "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_free_split26s": (
        "deebc1983d36afac",
        (
            (),
            (
                " bother ",
                " matter who gets wh",
                "any",
                "bothered",
                "care",
                "fussed",
                "makes no odds",
                "mind",
                "same ",
                "way",
            ),
            True,
        ),
        (
            (
                "_FREE_SPLIT26S",
                (
                    "value",
                    "\"(?:any|either) (?:which )?way(?: round| around)?(?: you (?:like|want|fancy|please))?|(?:i )?(?:don't|do not) mind who gets (?:what|which)(?: one)?|(?:it )?makes no odds who gets (?:what|which)(?: [a-z]+)?|(?:it )?(?:doesn't|does not) matter who gets (?:what|which)(?: [a-z]+)?\"",
                ),
            ),
            (
                "_INDIFFERENT26S",
                (
                    "value",
                    "\"any|(?:(?:she|he|they|i|we)(?:'s|'re|'m| is| are| am) )?not (?:fussed|bothered)(?: which)?|(?:she|he|they|i|we) (?:doesn't|don't|does not|do not) (?:care|mind)(?: which)?|(?:it )?(?:doesn't|does not) bother (?:me|her|him|them|us)(?: which)?|(?:(?:it's|it is) )?all (?:the )?same (?:to|for) (?:me|her|him|them|us)|(?:it )?makes no odds(?: which)?\"",
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise3:_fronted_except28r": (
        "b6c73ba9aaa42e7e",
        ((), ("apart from", "aside from", "bar", "but for", "except", "other than"), True),
        (
            (
                "_FRONTED_EXCEPT28R",
                (
                    "pattern",
                    "^(?P<open>(?:except(?: for)?|apart from|other than|bar|but for|aside from) (?P<x>[^,.;:!?]+?))\\s*,\\s*(?P<rest>[^.;:!?]+)(?P<end>[.;:!?]*\\s*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_fronted_to33t": (
        "6e15592ac9670338",
        ((), ("to ", "whichever "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_gather_up31r": (
        "8a0e992d427b5835",
        ((), ("collect", "gather", "round"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_give_both28s": (
        "54042418dc3a3288",
        ((), ("both", "the two"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_going_over30r": (
        "32ba2770ca0c04fc",
        ((), (" to ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_got_them33t": ("7a5e03679b2d89d8", ((), ("got",), False), ()),
    "hltl.grounding._normalise3:_happy_with31r": (
        "23c81c349cde7e01",
        ((), ("'d be", "will be", "would be"), True),
        (
            (
                "_HAPPY_WITH31R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?:would be|'d be|will be) (?:quite |perfectly |very )?(?:happy|fine|glad|content|pleased) (?:with|to get|to have) (?P<x>(?:either |both )?(?:the|a|an|one of the|any of the) [^,;:.!?]+?)(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_i_mean_after30r": (
        "0217db48b57a4e6a",
        ((), (" i mean",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_in_hand28r": ("c4129466679cf450", ((), ("hand",), False), ()),
    "hltl.grounding._normalise3:_included27r": (
        "a7f01e41c9ce9365",
        ((), ("includ",), False),
        (
            (
                "_INCLUDED27R",
                (
                    "pattern",
                    ",\\s*(?:(?:and )?(?:the )?([\\w ]+?) included|including (?:the )?([\\w ]+?))(?=\\s*(?:[.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_into_with_them32r": (
        "0e91cf7b1f1712b6",
        ((), (" with ",), True),
        (
            (
                "_INTO_WITH_THEM32R",
                (
                    "pattern",
                    "^(?P<x>the [a-z ]+?) (?:both |all )?(?:want|need|could do with) (?:a )?[a-z]+ing\\s*,\\s*(?:so )?(?P<prep>into|in|onto|on) (?P<s>the [a-z ]+?) with (?:them|the pair of them|both of them|the lot|the two of them|the pair|the two)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_is_to28s": (
        "b67e752041bc8ec5",
        ((), (" the two of them", " to "), True),
        (
            ("_PERSON28S", ("value", "'person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+'")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_isnt_adjective32r": (
        "cfb4c5048ad39998",
        ((), ("the one ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_its_who_cue31r": (
        "a17138ba67a45c35",
        ((), ("it",), True),
        (
            (
                "_ITS_WHO_CUE31R",
                (
                    "pattern",
                    "(?P<cue>,\\s*(?:(?:(?:no,? |(?:eh|ah),? no,? |(?:oh|eh|ah),? )?(?:sorry|so sorry)(?:,? (?:no|wrong))?(?:,? i meant?)?|whoops|oops|(?:no,? )?my (?:mistake|bad)|pardon me|i meant?|i misspeak|i misspoke|let me rephrase|(?:or )?rather|(?:no,? )?(?:strike|scratch|belay|revert|cancel) that(?: order)?|(?:wait|no wait|no),? (?:revert|scratch|strike|cancel) that|correction|no,? (?:wait|hold on|hang on)|(?:eh|ah),? no|nay(?:,? i misspeak)?|no,? sorry|no,? no)|no|wait|hang on|hold on|actually)\\s*,\\s*)it(?:'s| is| was) (?P<p>[A-Za-z][\\w ]*?)(?:'s turn| who (?:wants|wanted|needs|needed|asked for|ordered|is after|was after) (?:it|them|that|those)| who asked)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_kind_choice33t": (
        "84fc08beb37e9db6",
        ((), ("one of the ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_kindly_verbs29s": (
        "1672945be561bcfe",
        ((), (" away ", "appreciated", "grateful", "obliged", "thankful", "would you mind"), True),
        (
            (
                "_GRATEFUL29S",
                (
                    "pattern",
                    "\\s*[,.!]\\s*(?:i'm |i am |we're |we are )?(?:ever so |very |so |really |most |much |truly )?(?:grateful|obliged|thankful|appreciated)(?: (?:to you|indeed))?\\s*[.!]*\\s*$",
                    34,
                ),
            ),
            (
                "_MIND_LETTING29S",
                (
                    "pattern",
                    "\\bwould you mind(?: (?:awfully|terribly|very much|at all))? letting\\b",
                    34,
                ),
            ),
            (
                "_TIDY_AWAY29S",
                (
                    "pattern",
                    "\\b(?:tidy|tidying|tidied) (?P<what>(?:the|that|this|those|these|both|all the) [a-z]+(?: [a-z]+)?|it|them) away (?P<where>in|into|on|onto)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_laid_out30r": (
        "98a0f10ed5035e14",
        ((), (" out ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_leave_first31r": (
        "a7900a1ba5451629",
        ((), ("leave ",), True),
        (
            (
                "_LEAVE_FIRST31R",
                (
                    "pattern",
                    "^(?:just )?leave (?P<x>the [a-z]+(?: [a-z]+)?)(?: (?:alone|be|where it is|where they are|there|for now|out of it))?\\s*[;:.]\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_leave_on30r": (
        "045722a982f921c9",
        ((), ("leave ",), True),
        (
            (
                "_LEAVE_ON30R",
                (
                    "pattern",
                    "(?P<cue>\\bno,\\s*)(?:just )?leave (?:it|them) (?:out )?(?P<on>(?:on|onto|in|into) (?:the )?(?P<s>[a-z]+(?: [a-z]+)??))(?P<inst> instead)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_leave_where31r": (
        "0c5d6a2bd0fd36fe",
        (
            (),
            ("can remain", "can stay", "is staying", "leave ", "remains", "should stay", "stays"),
            True,
        ),
        (
            (
                "_LEAVE_WHERE31R",
                (
                    "pattern",
                    ",\\s*(?:but |and )?(?:(?:just |please )?leave (?P<x>the [a-z]+(?: [a-z]+)?) (?:where it is|where they are|alone|be|as it is|as they are|in place|untouched)|(?P<y>the [a-z]+(?: [a-z]+)?) (?:can stay|stays|should stay|can remain|remains|is staying) (?:where it is|put|there|behind|in place|as it is))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_leave_where33t": (
        "af8c549c7e966b52",
        ((), ("all of it", "everything", "the lot"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_leaving_out30r": (
        "f67874200f51daf7",
        ((), ("but leave", "leaving"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_load_up33t": (
        "2810add3a4040151",
        ((), (" up with ", " with "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_lot_is30r": (
        "1551060954fe3964",
        ((), ("all of it", "everything", "the lot", "the whole lot", "whatever"), True),
        (
            (
                "_ALL_WORDS30R",
                (
                    "value",
                    '"(?:the whole lot|the lot|everything|all of it|whatever(?:\'s| is) (?:there|here)|whatever there is)"',
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise3:_matters_which28s": (
        "704c1c54f8926162",
        ((), (" bother me ", "'ll matter", "matters", "will matter"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_meant_to_say31r": (
        "967fdfe3dade7e63",
        ((), (" to say", "be", "should"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_namely31r": (
        "ded5f23c033dbfca",
        ((), ("bits", "items", "objects", "things"), True),
        (
            (
                "_NAMELY31R",
                (
                    "pattern",
                    "\\b(?P<n>two|three|four|five|2|3|4|5) (?:things|items|objects|bits)(?P<mid>(?: [a-z][\\w ]*?)?),\\s*(?:namely|that is|i\\.e\\.,?|to wit|specifically|viz\\.?|which are) (?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\\s*|,? and )(?:the |a |an )?[a-z]+(?: [a-z]+)?)+)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_need_over33t": (
        "92aca7ffc30df05f",
        ((), (" over ", "like "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_needs_a30r": (
        "8173515c9ee5c00d",
        ((), ("could do with", "could use", "fancies", "needs", "wants", "would like"), True),
        (
            (
                "_NEEDS_A30R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?:needs|wants|could use|could do with|would like|fancies) (?:a|an|some|something) (?P<w>[a-z]+(?: [a-z]+)??)(?:,\\s*so\\s+(?P<so>\\S.*)|\\s+and (?:will|would|'ll) (?P<v>take|have|accept|settle for) (?P<rest>\\S.*))$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_no_need_first32r": (
        "c7b5eab38b3feb24",
        ((), ("no need to ",), True),
        (
            (
                "_NO_NEED_FIRST32R",
                (
                    "pattern",
                    "^(?:there's )?no need to (?:set|put|place|leave) (?P<x>the [a-z ]+?) (?:down )?(?:first|beforehand)\\s*,\\s*(?:just )?(?P<rest>(?:pass|hand|give|bring) it\\b[^,;:.!?]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_no_one_elses31r": (
        "a7c319a53494cbb1",
        ((), (" and no",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_no_such_place32r": (
        "ba42f3f6823a1014",
        ((), ("there",), True),
        (
            (
                "_NO_SUCH_PLACE32R",
                (
                    "pattern",
                    "^(?:put|place|set|pop|leave) (?P<x>the [a-z ]+?) (?:on|onto|in|into)\\s*,\\s*(?:oh )?wait\\s*,\\s*there(?:'s| is) no (?P<s>[a-z]+)(?: here)?\\s*,\\s*(?:so )?(?:just )?(?P<rest>(?:give|hand|pass|bring|take) it\\b[^,;:.!?]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_no_x_just31r": (
        "18e843bfeceb6fdf",
        ((), ("just", "only"), True),
        (
            (
                "_NO_X_JUST31R",
                (
                    "pattern",
                    "^no (?P<x>[a-z]+(?: [a-z]+)?) (?:for|to) (?P<p>[A-Za-z][\\w ]*?)(?: today| this time| now)?,\\s*(?:just|only) (?:his|her|their|the) (?P<y>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_no_yes29s": (
        "75bacd0055dd34b1",
        ((), ("no",), True),
        (
            (
                "_NO_YES29S",
                (
                    "pattern",
                    "(?P<head>^[^.!?;]*?)\\s*(?:,|—|–|\\s-)\\s*(?:no|nope)(?:,?\\s*(?:wait|hang on|hold on))?\\s*,?\\s*(?:yes|yeah|yep)(?:,?\\s*(?:that's|that is) (?:right|it|correct))?\\s*,\\s*(?P<again>[^,.!?—–]+?)(?:\\s*,\\s*(?:that's right|that is right|carry on|go on|it's only (?:her|him|them)))?\\s*(?P<end>[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_none_there30r": (
        "4072aa42b96eb307",
        ((), (" it ",), True),
        (
            (
                "_NONE_THERE30R",
                (
                    "pattern",
                    "^(?P<x>(?:the )?[a-z]+(?: [a-z]+)??) (?:on|onto|in|into) (?:the )?[a-z]+(?: [a-z]+)??,\\s*(?:oh )?no,\\s*(?:(?:there isn't one|there is not one|there's no (?:such )?[a-z]+|there is no [a-z]+|we don't have one|we haven't got one)\\s*[,;]\\s*)?(?:just )?(?P<v>give|hand|pass|take|bring) it (?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_again30r": (
        "d8fadcc08e322ffe",
        ((), ("not ",), True),
        (
            (
                "_NOT_AGAIN30R",
                (
                    "pattern",
                    "(?P<cue>(?:^|[,.;!?]\\s*)(?:wait|no|sorry|hang on|hold on|oops|actually),\\s*)(?P<q>(?:the )?[A-Za-z][\\w ]*?),\\s*not (?P<p>(?:the )?[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_cleft30r": (
        "dd266872feb6f732",
        ((), (" not ",), True),
        (
            (
                "_NOT_CLEFT30R",
                (
                    "pattern",
                    "^it(?:'s| is) not (?P<said>the [a-z ]+?) (?:is after|wants|needs|asked for|would like|'s after),\\s*it(?:'s| is) (?P<y>the [a-z ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_first28r": (
        "82436c80fc13c944",
        ((), ("do not", "don't", "needn't", "no need", "not ", "you don't"), False),
        (),
    ),
    "hltl.grounding._normalise3:_not_first29r": (
        "920880a3435a0ad9",
        ((), (" leave ", "ne of ", "thing"), True),
        (
            (
                "_LEAVE_WHERE29R",
                (
                    "pattern",
                    "^(?:please )?(?:don't|do not) leave (?P<x>the [a-z ]+?) (?:where it is|where they are|lying there|sitting there|there)\\s*[;,:.]\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
            (
                "_NONE_FOR29R",
                (
                    "pattern",
                    "^(?:none of (?:it|them|that|those)|nothing|not a thing) (?:goes |is )?(?:to|for) (?P<p>[A-Za-z][\\w ]*?)\\s*[;,:.]\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_for29r": (
        "2caf60d89596cb35",
        ((), ("are not", "aren't", "is not", "isn't"), True),
        (
            (
                "_NOT_FOR29R",
                (
                    "pattern",
                    "^(?P<x>the [a-z ]+?) (?:aren't|are not|isn't|is not) (?:for|meant for) (?P<p>[A-Za-z][\\w ]*?)\\s*[;,]\\s*(?:they're|they are|it's|it is) (?P<q>[A-Za-z][\\w ]*?)'s\\s*,\\s*so\\s+(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_for_but29s": (
        "765e3d5756097973",
        ((), (" for ",), True),
        (
            (
                "_NOT_FOR_BUT29S",
                (
                    "pattern",
                    "^(?P<what>the [a-z]+(?: [a-z]+)?) (?P<be>is|are|'s|'re)(?: not|n't) for (?P<no>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)\\s*,\\s*(?:(?:i tell you|mind|honestly|i'm telling you|you know)\\s*,\\s*)?(?:but )?(?:they|it)(?:'re|'s| are| is) for (?P<who>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)(?P<end>\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_for_them31r": (
        "a3a9ebf00d6bfe2b",
        ((), (" do", " for "), True),
        (
            (
                "_NOT_FOR_THEM31R",
                (
                    "pattern",
                    "^(?P<req>[^;.!?]+?)\\s*[,;.]\\s*(?:but |and )?(?:(?P<p>[A-Za-z][\\w ]*?) (?:doesn't|does not|don't|do not) (?:need|want|get) (?P<x>it|them|the [a-z]+(?: [a-z]+)?)|(?P<y>the [a-z]+(?: [a-z]+)?|it|they|that|those) (?:isn't|is not|aren't|are not|'s not|'re not) for (?P<q>[A-Za-z][\\w ]*?))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_not_other_person32r": (
        "b02a87f7b79d8882",
        ((), ("not ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_not_that28r": ("92dd653f48d7e0d6", ((), ("not ",), False), ()),
    "hltl.grounding._normalise3:_not_to_semi31r": (
        "461248fd711a0257",
        ((), ("not ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_not_wanted30s": (
        "9195f9f2c40a0a9c",
        (("n't",), (" not ",), False),
        (),
    ),
    "hltl.grounding._normalise3:_not_wanted32r": (
        "f7e4e049ae2d5e0f",
        (
            (),
            (
                "is not to",
                "isn't to",
                "must not",
                "mustn't",
                "need",
                "should not",
                "shouldn't",
                "want",
            ),
            True,
        ),
        (
            (
                "_NOT_WANTED32R",
                (
                    "pattern",
                    "\\s*[;,]\\s*(?:but |and )?(?P<who>[A-Za-z][\\w ]*?) (?:doesn't|does not|don't|do not) (?:want|need) (?P<x>(?:the|a|an|any) [a-z ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_SHOULDNT_GET32R",
                (
                    "pattern",
                    "\\s*[;,]\\s*(?:but |and )?(?P<who>[A-Za-z][\\w ]*?) (?:shouldn't|should not|mustn't|must not|isn't to|is not to) (?:get|have|be given) (?:it|them)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_object_first28s": (
        "7169643b56572f97",
        ((), ("give", "hand", "pass"), True),
        (
            ("_PERSON28S", ("value", "'person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+'")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_objects_first33t": (
        "f793af721f4fe530",
        ((), ("give ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_of_their_own31r": (
        "b5c558798ab340fa",
        ((), ("ach", "very"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_off_with30r": (
        "4dfa3b51e13d6638",
        ((), (" off with ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_one_for_each31r": (
        "7835e4fd0d2a424b",
        ((), (" and ",), True),
        (
            (
                "_ONE_FOR_EACH31R",
                (
                    "pattern",
                    "^(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\\s*|,? and )(?:the |a |an )?[a-z]+(?: [a-z]+)?)+),\\s*one (?:for|to) (?P<p>[A-Za-z][\\w ]*?),? and (?:one|the other) (?:for|to) (?P<q>[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_one_of_them26s": (
        "db06e7204de95cfb",
        ((), (" one of ", " one of them", "one of them,"), True),
        (
            ("_PERSON26", ("value", "'((?:person |mr |mrs |ms |miss |dr )?[a-z]+)'")),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise3:_one_said33t": (
        "42358fbbd8f6fd38",
        ((), (" together", "just the one pair", "not the ", "that's "), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_one_that_isnt31r": (
        "55865bdb8570df5f",
        ((), ("of the two",), True),
        (
            (
                "_ONE_THAT_ISNT31R",
                (
                    "pattern",
                    "^of the two(?: (?:things|items|objects))?,\\s*(?P<p>[A-Za-z][\\w ]*?) (?P<v>wants|needs|gets|should get|can have|would like) the one (?:that|which)(?:'s| is)? (?:isn't|is not|'s not|aren't|are not) (?:a (?:bag|packet|bottle|cup|box) of |the |an? )?(?P<x>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_after_person31r": (
        "be22f6d0cae0c028",
        ((), ("just", "only"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_only_got30r": (
        "080d2f3831ed697e",
        ((), (" and only one ", "and "), True),
        (
            (
                "_ONLY_GOT30R",
                (
                    "pattern",
                    "^(?:we've|we have|we) (?:only )?(?:got|have) (?:only |just )?(?:a single|one|the one|just the one) (?P<x>[a-z]+(?: [a-z]+)??)(?: going| left| here| to spare)?,\\s*and (?P<p>[A-Za-z][\\w ]*?) (?:is having|is getting|should have|should get|can have|gets|is to have) it(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_ONLY_ONE_HERE30R",
                (
                    "pattern",
                    "^(?:there's )?only one (?P<x>[a-z]+(?: [a-z]+)??) and only one (?:person|human|of you|one person)(?: here| around| about)?,\\s*so (?:she|he|they) (?:gets|can have|should have|is having) it(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_needs29r": (
        "70cb930bff670932",
        ((), (" only ",), True),
        (
            (
                "_ONLY_NEEDS29R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) only (?P<v>needs|wants|requires|would like|asked for)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_not30r": (
        "798a28d3d09bef47",
        ((), (" not ", "but no "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_only_nothing_else32r": (
        "be0eff4a7f67f4b3",
        ((), ("nothing",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_only_one29r": (
        "5ae266584b7b322a",
        ((), ("there's ",), True),
        (
            (
                "_ONLY_ONE29R",
                (
                    "pattern",
                    "^there's (?:only |just )?(?:a single|the one|one|just the one) (?P<x>[a-z ]+?),\\s*and (?P<p>[A-Za-z][\\w ]*?) (?:should have|should get|can have|gets|is to have|wants|needs) it(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_one_here32r": (
        "a959edece3f3f3a0",
        ((), (" here", " only "), True),
        (
            (
                "_ONLY_ONE_HERE32R",
                (
                    "pattern",
                    "^(?P<head>.+?) (?P<prep>to|for) (?P<q>[A-Za-z][\\w ]*?),\\s*(?:(?:no|sorry|oops|wait),\\s*)+there(?:'s| is) only (?P<p>[A-Za-z][\\w ]*?) here,\\s*(?:so )?(?:to|for) (?:her|him|them)(?: then| instead)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_ONLY_ONE_HERE_SO32R",
                (
                    "pattern",
                    "^(?P<head>.+?) (?P<prep>to|for) (?P<q>[A-Za-z][\\w ]*?)\\.\\s*(?:oops|sorry|whoops),?\\s*(?:(?:wrong (?:bay|room|person|one|ward)|no),?\\s*)?it(?:'s| is) (?:just|only) (?P<p>[A-Za-z][\\w ]*?) here,?\\s*so (?P<p2>[A-Za-z][\\w ]*?|she|he|they) (?:gets|has|should get|can have) it(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_one_item31r": (
        "75991ab67b8b2344",
        ((), ("item", "object", "thing"), True),
        (
            (
                "_ONLY_ONE_ITEM31R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?P<v>wants|needs|would like|is after|asked for|gets|should get|can have) (?:only |just )?(?:one|a single) (?:thing|item|object),?\\s*(?:and|which is) (?:it's|it is|that's|that is|that'll be|it'll be)? ?(?P<x>(?:the |that )[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_one_who30r": (
        "d125fa1b6c0ab3b5",
        ((), (" the only ",), True),
        (
            (
                "_ONLY_ONE_WHO30R",
                (
                    "pattern",
                    ",\\s*(?P<who>she|he|they)(?:'s| is|'re| are) the only (?:one|ones|person|people)(?P<said>(?: [a-z][a-z' -]*?)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_the_one32r": (
        "a7c76c76cb5c963f",
        ((), (" only ",), True),
        (
            (
                "_ONLY_THE_ONE32R",
                (
                    "pattern",
                    ",\\s*(?:and )?there(?:'s| is) only (?:the )?one(?: of (?:it|them))?(?:\\s*,\\s*so no (?:mix-?ups|confusion|mistakes))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_these32r": (
        "ca2afc025d63945b",
        ((), (" the only ",), True),
        (
            (
                "_ONLY_THESE32R",
                (
                    "pattern",
                    "^there(?:'s| is) only (?P<x>the [a-z ]+?),? and (?P<p>[A-Za-z][\\w ]*?)(?:'s| is) the only (?:one|person) here,\\s*so (?:that's|it's) (?:simple|easy|straightforward)\\s*[:,;]\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_only_who30r": (
        "9b03437ea7b77c7b",
        ((), ("only ",), True),
        (
            (
                "_ONLY_WHO30R",
                (
                    "pattern",
                    "^only (?P<p>[A-Za-z][\\w ]*?) (?P<v>is to get|is to have|gets|should get|should have|can have)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_openers33t": (
        "5e4a19dac8c91baa",
        ((), ("'ll be", "'m off to", "going to", "listen", "nothing ", "quick as you like"), True),
        (
            (
                "_LATER24",
                (
                    "pattern",
                    "\\b(?:tomorrow|tonight|later|next|week|weekend|month|evening|afternoon|morning|lunch|dinner|breakfast|tea|hours?|minutes?|mins?|days?|o'clock|\\d)\\b",
                    34,
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_opens_a_fix29s": (
        "40b1924d054f2271",
        ((), ("actually", "hang on", "hold on", "sorry", "wait"), True),
        (
            (
                "_OPENS_A_FIX29S",
                (
                    "pattern",
                    "(?P<stop>[.!]\\s+)(?:oh,?\\s*|er,?\\s*|um,?\\s*)?(?:sorry|so sorry|hang on|hold on|actually|wait)\\s*,\\s*(?:(?P<slip>my mistake|my bad|i misspoke|i misspeak|i misheard (?:her|him|them|you)|i(?:'ve| have)? got (?:that|it) wrong|i said (?:that|it) wrong)\\s*,\\s*|(?P<not>not (?P<said>the [a-z]+(?: [a-z]+)?)\\s*,\\s*)|change (?:that|it) to\\s+)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_or_not28s": (
        "75600638a96e005e",
        ((), ("or not",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_other_isnt32r": (
        "cdbd911f718ea79b",
        ((), ("the other ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_other_not31r": (
        "dcb1e03cfd0fb98b",
        ((), ("the non-", "the other "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_other_one32r": (
        "094c12ed92c46647",
        ((), (" the other one",), True),
        (
            (
                "_OTHER_ONE32R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?:said|says|thinks|reckons|told me)(?: that)? (?P<x>the [a-z ]+?) (?:itches|is itchy|scratches|is scratchy|is too (?:small|big|heavy|cold|warm|thin)|is (?:dirty|broken|cracked|wet)|doesn't fit)\\s*,\\s*so (?P<v>give|hand|bring|pass|take) (?P<pro>him|her|them) the other one(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_other_two33t": (
        "778cb32a294fbed4",
        ((), ("either of the other ", "either of the others", "one of the other "), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_others_rest32r": (
        "b7028b289342c8ba",
        ((), (" the rest",), True),
        (
            (
                "_OTHERS_REST32R",
                (
                    "pattern",
                    ",\\s*(?:the|our) [a-z]+s (?:will|can|'ll) (?:sort|deal with|handle|see to|take care of|do) the rest(?: (?:later|themselves))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_out_of_reach27": (
        "d48aa17023daccd9",
        ((), ("out of",), False),
        (),
    ),
    "hltl.grounding._normalise3:_owned_not30r": (
        "bbad19217a8e1300",
        ((), ("are not", "aren't", "is not", "isn't"), True),
        (
            (
                "_OWNED_NOT30R",
                (
                    "pattern",
                    "^(?P<x>the [a-z]+(?: [a-z]+)??) (?:is|are|'s|'re) (?P<p>[A-Za-z][\\w ]*?)'s\\s*[;,]\\s*(?:but )?(?P<y>the [a-z]+(?: [a-z]+)??) (?:isn't|aren't|is not|are not)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_pair_back30r": (
        "9f6ea71781014a7a",
        ((), ("both of them", "the pair", "the two"), True),
        (
            (
                "_PAIR_BACK30R",
                (
                    "pattern",
                    "^(?P<remark>[^,;.]*?\\b(?:both|the two|the pair of) (?P<xs>[a-z]+s)\\b[^,;.]*),\\s*so\\s+(?P<req>[^,;.]*?\\b)(?P<pair>the pair|the two|both of them|the two of them)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_pair_listed28s": (
        "e986e10d48f9bb90",
        ((), (" and ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_person_one30s": ("661953eb74c1deac", ((), (" one",), False), ()),
    "hltl.grounding._normalise3:_place_to30r": (
        "238de91533e42598",
        ((), ("to ",), True),
        (
            (
                "_PLACE_TO30R",
                (
                    "pattern",
                    "^(?P<verb>(?:please )?(?:put|place|set|pop) )?(?P<x>(?:the )?[a-z]+(?: [a-z]+)??) (?:on|onto|in|into) (?:the )?(?P<s>[a-z]+(?: [a-z]+)??),\\s*(?:sorry|no|oops|whoops|my mistake),\\s*(?:i meant |i mean |no,\\s*)?to (?P<p>[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_placed_for30r": (
        "59f84c3dcbbaeda6",
        ((), (" for ",), True),
        (
            (
                "_PLACED_FOR30R",
                (
                    "pattern",
                    "\\b(?P<on>(?:on|onto|into|in) (?:the )?[a-z]+(?: [a-z]+)??) for (?P<p>[A-Za-z][\\w ]*?)'s (?P<w>[a-z]+(?: [a-z]+)??)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_placed_for33t": ("11749452e54383c8", ((" for ",), (), False), ()),
    "hltl.grounding._normalise3:_places_said33t": (
        "b48bff011fe1f31b",
        ((), (" ones,", " over", " the ", "not the ", "the other "), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_play_with31r": (
        "6f2880c83cd4d552",
        ((), (" play with ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_pronoun_is_to30r": (
        "cafd1195abe0a49a",
        ((), (" to ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_purpose_ing33t": ("56c66530105ed94b", (("ing",), (), False), ()),
    "hltl.grounding._normalise3:_purpose_of28r": ("8dd7cb6cd322685b", (("'s ",), (), False), ()),
    "hltl.grounding._normalise3:_rather_after30r": (
        "0cfbfff509d69ee2",
        ((), (" rather",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_rather_than30r": (
        "da1175ef16cdc555",
        ((), ("rather than ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_reach_first32r": (
        "4d695f1bcbcba841",
        ((), ("whichever",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_ready_for29s": (
        "46d3df4fa62f9ee2",
        ((), ("ready for ",), True),
        (
            (
                "_READY_FOR29S",
                (
                    "pattern",
                    "(?:\\s*,\\s*|\\s+)(?:all |nice and )?ready for (?P<what>[a-z' -]+?)\\s*(?P<end>[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_remark_then30r": (
        "2e13f030f03bb4af",
        ((), (" and ",), True),
        (
            (
                "_AND_NOT_FUSSY30R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?)(?:'s| is) (?P<said>[a-z][a-z' -]*?) and (?P<not>not (?:fussy|bothered|particular|picky))(?=\\s*,\\s*so\\b)",
                    34,
                ),
            ),
            (
                "_THEY_AFTER30R",
                (
                    "pattern",
                    "^(?P<pq>[A-Za-z][\\w ]*? and [A-Za-z][\\w ]*?) (?:are|'re) (?P<said>[a-z][a-z' -]*?)\\s*[;,]\\s*(?:so )?they (?P<rest>(?:can|could|should|will|each|both|get|have)\\b.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_remarks28r": (
        "c29c445cd5cb950d",
        ((), (" so", "could ", "need", "the poor ", "want"), True),
        (
            (
                "_REMARKS28R",
                (
                    "compiled",
                    "single",
                    (
                        (
                            "\\s*,\\s*(?:and )?the poor (?:thing|dear|love|soul|lamb|mite|lad|lass)(?:'s| is| has) (?P<said>[a-z][a-z' ]*?)(?=\\s*[.!]?\\s*$)",
                            34,
                        ),
                        (
                            "\\s*,\\s*(?:and )?(?P<who>they|it|the [a-z]+)(?:'s| is)? (?:needs?|wants?|could (?:do with|use)) (?P<said>(?:a |an |some )?[a-z][a-z' ]*?)(?=\\s*[.!]?\\s*$)",
                            34,
                        ),
                        (
                            "^(?P<who>(?:the|my|our) [a-z]+)(?:'s| is| has) (?P<said>gone|left|arrived|finished|off|here|done)(?: (?:now|home|for the day|already))?,? so\\s+",
                            34,
                        ),
                    ),
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise3:_run30": ("325858544ac48012", ((), ("run",), False), ()),
    "hltl.grounding._normalise3:_run_to28s": (
        "f0f3773c5baa37aa",
        ((), ("run ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_said_again33t": (
        "8bce85ae83e1034c",
        ((" or ",), (" left ", "either ", "then the ", "while "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_said_aside27r": (
        "dfc888b01ca2b709",
        (
            (),
            (
                " as ",
                " as well",
                " back",
                " too",
                "all ",
                "alongside",
                "beside",
                "et",
                "matter",
                "mind",
                "next to",
                "ot",
                "that are",
                "that aren't",
                "that is",
                "that isn't",
                "whichever",
                "whoever",
            ),
            True,
        ),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._normalise3:_says_she_is28s": (
        "93167b8c7e718afb",
        ((), ("he is", "he's", "they are", "they're"), True),
        (
            ("_PERSON28S", ("value", "'person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+'")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_single28r": (
        "5bdf92fa8b21b7a9",
        ((), (" of ", "single"), False),
        (),
    ),
    "hltl.grounding._normalise3:_sit_stand31r": (
        "5faf58004a9ba40c",
        ((), ("both", "the"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_sizes30s": (
        "5d7a042867d3436a",
        ((), ("e",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_slip31r": (
        "febef4eaff0197b1",
        ((), (" got ", "i tell a lie", "ixed", "silly me", "uddled", "what am i saying"), True),
        (
            (
                "_SLIP_AFTER_CUE31R",
                (
                    "pattern",
                    "(?P<cue>,\\s*(?:(?:(?:no,? |(?:eh|ah),? no,? |(?:oh|eh|ah),? )?(?:sorry|so sorry)(?:,? (?:no|wrong))?(?:,? i meant?)?|whoops|oops|(?:no,? )?my (?:mistake|bad)|pardon me|i meant?|i misspeak|i misspoke|let me rephrase|(?:or )?rather|(?:no,? )?(?:strike|scratch|belay|revert|cancel) that(?: order)?|(?:wait|no wait|no),? (?:revert|scratch|strike|cancel) that|correction|no,? (?:wait|hold on|hang on)|(?:eh|ah),? no|nay(?:,? i misspeak)?|no,? sorry|no,? no)|no|wait|hang on|hold on|oh)\\s*),\\s*(?:i tell a lie|i(?:'ve| have)? got (?:them|it|that|those|this|these) (?:all )?(?:mixed up|muddled(?: up)?|wrong|the wrong way round|back to front)(?: again)?|i(?:'ve| have)? (?:mixed|muddled) (?:them|it|that|those) up(?: again)?|silly me|what am i saying)\\s*,\\s*(?=\\S)",
                    34,
                ),
            ),
            (
                "_SLIP_ALONE31R",
                (
                    "pattern",
                    "(?P<lead>,\\s*)(?:i tell a lie|i(?:'ve| have)? got (?:them|it|that|those|this|these) (?:all )?(?:mixed up|muddled(?: up)?|wrong|the wrong way round|back to front)(?: again)?|i(?:'ve| have)? (?:mixed|muddled) (?:them|it|that|those) up(?: again)?|silly me|what am i saying)\\s*,\\s*(?=\\S)",
                    34,
                ),
            ),
            (
                "_SLIP_CLOSING31R",
                (
                    "pattern",
                    "[,;.!]\\s*(?:(?:oh|ah|no|sorry|wait|whoops|oops)\\s*,?\\s*)*(?P<said>(?:i tell a lie|i(?:'ve| have)? got (?:them|it|that|those|this|these) (?:all )?(?:mixed up|muddled(?: up)?|wrong|the wrong way round|back to front)(?: again)?|i(?:'ve| have)? (?:mixed|muddled) (?:them|it|that|those) up(?: again)?|silly me|what am i saying))(?:\\s*,?\\s*(?:sorry|again|there))*\\s*[.!]?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_slip_owned29s": (
        "049aaa3dfbd396e1",
        ((), (" got ", "mistake", "silly me", "wrong"), True),
        (
            (
                "_SLIP_CUE29S",
                (
                    "pattern",
                    "\\s*,\\s*(?:oh,?\\s*)?(?:i (?:make|made|'ve made|have made) (?:a |my )?mistake|i(?:'ve| have)? got (?:that|it) (?:wrong|mixed up|muddled)|(?:oh,? )?silly me|i(?:'ve| have)? (?:read|heard|got|misread|misheard) (?:the|that|it|my) (?:[a-z]+ )?wrong)\\s*,\\s*",
                    34,
                ),
            ),
            (
                "_SLIP_LAST29S",
                (
                    "pattern",
                    "\\s*,\\s*(?:(?:sorry|oops|whoops),?\\s*)?(?:i (?:make|made|'ve made|have made) (?:a |my )?mistake|i(?:'ve| have)? got (?:that|it) (?:wrong|mixed up|muddled)|(?:oh,? )?silly me|i(?:'ve| have)? (?:read|heard|got|misread|misheard) (?:the|that|it|my) (?:[a-z]+ )?wrong)\\s*[.!]*\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_so_can32r": (
        "5287f14cb53e6527",
        ((), (" can ",), True),
        (
            (
                "_SO_CAN32R",
                (
                    "pattern",
                    "^(?P<head>[^,;:.!?]+?)\\s*,?\\s*so (?:that )?(?P<p>[A-Za-z][\\w ]*?) can (?P<v>[a-z]+)(?: (?:with|at|on))? (?:them|it)(?: (?:about|around|later|there|in peace))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_solitary31r": (
        "d34f1a0fe22e5a18",
        (
            (),
            (
                "is enough",
                "is fine",
                "lone",
                "one and only",
                "only remaining",
                "single",
                "sole",
                "solitary",
                "will do",
                "would do",
            ),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise3:_something_to30r": (
        "711a254693046a5a",
        ((), (" something",), True),
        (
            (
                "_SOMETHING_TO30R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?P<v>needs|wants|would like) something(?: to (?P<why>[a-z][a-z' ]*?))?\\s*[;:]\\s*(?P<rest>(?:the|a|an) \\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_sorry_after30r": (
        "058dfe5af460e6a0",
        ((), ("sorry",), True),
        (
            (
                "_SORRY_AFTER30R",
                (
                    "pattern",
                    ",\\s*sorry\\s*[,;:-]\\s*(?P<why>[a-z][a-z' -]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_split29r": (
        "0be9a6f67b0ae7b5",
        ((), (" between ",), True),
        (
            (
                "_SPLIT29R",
                (
                    "pattern",
                    "^(?:please )?(?:split|share|divide) (?P<x>the [a-z ]+?) between (?P<p>[A-Za-z][\\w ]*?) and (?P<q>[A-Za-z][\\w ]*?),\\s*one (?:apiece|each)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_split_two31r": (
        "82eb3644b933b67e",
        ((), (" between ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_split_way31r": (
        "1a8b9fc063cdba84",
        ((), (" between ",), True),
        (
            (
                "_SPLIT_WAY31R",
                (
                    "pattern",
                    "^(?P<head>(?:please )?(?:split|share|divide) the [a-z ]+? between [A-Za-z][\\w ]*? and [A-Za-z][\\w ]*?),\\s*(?:whichever|either|any) way(?: round| around)?(?: (?:you|u) (?:like|want|please|prefer|fancy))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_state_and_want30r": (
        "de91293b024f3db9",
        ((), (" and ",), True),
        (
            (
                "_STATE_AND_WANT30R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?)(?:'s| is| has) (?P<said>[a-z][a-z' -]*?) and (?:just |only |also )?(?P<v>needs|wants|would like|'d like|is after|could use)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_stays_on33t": ("d52624c9bb109f3f", ((), ("stay",), False), ()),
    "hltl.grounding._normalise3:_stays_put30r": (
        "f54e21f6a35f7445",
        ((), ("can stay", "is staying", "remains", "stays"), True),
        (
            (
                "_STAYS_PUT30R",
                (
                    "pattern",
                    "\\s*;\\s*(?:and )?(?P<x>the [a-z]+(?: [a-z]+)??) (?:stays|can stay|is staying|remains) (?:put|where it is|here|there)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_stays_put32r": (
        "c4949a35d9394b08",
        ((), ("the ",), True),
        (
            (
                "_STAYS_PUT32R",
                (
                    "pattern",
                    "\\s*[;,]\\s*(?:but |and )?(?P<x>the [a-z ]+?) (?:stays|stay|is staying|can stay) (?:put|where it is|here|there)(?:\\s*,\\s*(?:just )?leave it(?: alone| be| there)?)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_surface_busy29s": (
        "06b7ccdf6cbe60e1",
        (
            (),
            (
                " need ",
                "all over ",
                "cleaning",
                "clearing",
                "doing",
                "dusting",
                "painting",
                "polishing",
                "sorting",
                "tidying",
                "using",
                "wiping",
                "working on",
            ),
            True,
        ),
        (
            (
                "_SURFACE_BUSY29S",
                (
                    "pattern",
                    "\\s*,\\s*(?:(?:and|so|as|because|cos|since) )?(?:i(?:'m| am) (?:just |busy )?(?:clearing|cleaning|wiping|tidying|using|working on|doing|dusting|sorting|painting|polishing) (?P<a>(?:the|my) [a-z]+)|i need (?P<b>(?:the|my) [a-z]+)(?: (?:clear|free|empty))?(?: for (?:my |the |a |an |some )?[a-z]+(?: [a-z-]+){0,2})?|i need to (?:do|clean|wipe|clear|dust|tidy|use|sort|paint|polish) (?P<c>(?:the|my) [a-z]+)|i(?:'ve| have) got (?:[a-z]+ ){1,2}all over (?P<d>(?:the|my) [a-z]+))\\s*[.!?]*\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_taken_home32r": (
        "0ed8abe3d1ab8f67",
        ((), (" taking ",), True),
        (
            (
                "_TAKEN_HOME32R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?)(?:'s| is) taking (?P<x>(?:the|both|all|everything)\\b[^;:.!?]*?) (?:home|away|back)(?: with (?P<pro>her|him|them))?(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_that_there27r": (
        "6587f96d5283861d",
        ((), ("here",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_the_one_for28r": (
        "612105f42cb74a14",
        ((), ("the one",), False),
        (),
    ),
    "hltl.grounding._normalise3:_theres_the30r": (
        "8b2bbe5389f45a8a",
        ((), (" with ", "there"), True),
        (
            (
                "_THERES_THE30R",
                (
                    "pattern",
                    "^there(?:'s| is) (?:the only|only the|the one|just the|the) (?P<x>[a-z]+(?: [a-z]+)??)(?: here| there)?(?:\\s*,\\s*(?P<said>[a-z][a-z' ]*?))?\\s*[;:]\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
            (
                "_WITH_IT30R",
                (
                    "pattern",
                    "^(?P<dir>over|across|up|down|round) to (?P<p>[A-Za-z][\\w ]*?) with (?P<x>it|them|the [a-z]+(?: [a-z]+)??)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_these_listed31r": (
        "90501513aaeb0951",
        ((), ("one of th",), True),
        (
            (
                "_THESE_LISTED31R",
                (
                    "pattern",
                    "(?:\\b(?:any|either|just) )?\\bone of (?:these|those|them|the following|the (?P<n>two|three|four)(?: of them)?)\\s*:\\s*(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\\s*|,? (?:and|or) )(?:the |a |an )?[a-z]+(?: [a-z]+)?)+)(?P<end>\\s*(?:[.!;]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_things_here30r": (
        "fa098305717ae790",
        ((), (" here",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_trailing_remark34": (
        "32d484ace9feda29",
        ((",",), (), True),
        (("_TRAILING34", ("pattern", ",\\s*(?P<said>[^,;:.!?]+?)(?P<end>\\s*[.!]?)\\s*$", 32)),),
    ),
    "hltl.grounding._normalise3:_unknown_fixed33t": (
        "50878652393fddd7",
        ((), ("i mean",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise3:_verb_last27": (
        "5afcd25c9a970d7b",
        ((), ("bring", "deliver", "give", "hand", "leave", "pass", "place", "put", "set"), True),
        (
            ("_LAST_VERB27", ("value", "'(give|hand|pass|bring|deliver|put|place|set|leave)'")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise3:_waited30r": (
        "0913e7fc9dc59c11",
        ((), ("been waiting", "waited"), True),
        (
            (
                "_WAITED30R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?:has|'s|have) (?:waited|been waiting)(?: (?:long enough|ages|all day|a while))? for (?P<x>(?:the |that |this )?[a-z ]+?)(?: now| already)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_wanted_with28s": (
        "985f3c1ff14d5a2b",
        ((), (" with ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_wants_down30r": (
        "2bdd716a1a3797f7",
        ((), ("needs", "wants", "would like"), True),
        (
            (
                "_WANTS_DOWN30R",
                (
                    "pattern",
                    "^(?P<who>[A-Za-z][\\w' ]*?) (?:wants|needs|would like) (?P<x>(?:the|every|all|both) [a-z ]+?) (?:sent|put|moved|run|loaded) (?:down|along|onto|on|up) (?:the )?(?P<s>[a-z]+)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_wants_put29r": (
        "623ca769a0efd729",
        ((), ("needs", "wants", "would like"), True),
        (
            (
                "_WANTS_PUT29R",
                (
                    "pattern",
                    "^(?P<who>[A-Za-z][\\w' ]*?) (?:wants|needs|would like) (?P<x>(?:the |both |two |the two |the pair of |both the )[a-z ]+?)(?: (?:tidied|put|cleared|moved|packed|stowed|taken)(?: away| up| off)?| for (?P<why>[a-z' ]+?))?\\s*:\\s*(?:both|both of them|the pair|them|all|all of them|the lot) (?P<where>(?:up )?(?:onto|on|into|in) (?:the )?[a-z ]+?)(?:,? please)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_wants_sent30r": (
        "1a9d521eccbe370d",
        ((), ("asked for", "needs", "wants", "would like"), True),
        (
            (
                "_WANTS_SENT30R",
                (
                    "pattern",
                    "^(?P<who>[A-Za-z][\\w' ]*?) (?:wants|needs|would like|asked for|has asked for) (?P<x>(?:the |both |the two |both the )[a-z ]+?) (?:sent|taken|brought|carried|run|passed)(?P<dir>(?: over| across| back| up| down)?) to (?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_what_about30s": ("2c411bdd1b562a08", ((), ("about",), False), ()),
    "hltl.grounding._normalise3:_whatever_not28r": (
        "712ce4a65c75cb47",
        (("n't",), ("that is", "whatever"), False),
        (),
    ),
    "hltl.grounding._normalise3:_whatevers_here32r": (
        "f62f40f7bc0d7917",
        ((), ("everything ", "whatever"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise3:_which_arm29r": (
        "0b5c2f8ffc6afcba",
        ((), (" which ", "end up with", "get to", "go to", "reach"), True),
        (
            (
                "_REACH29R",
                (
                    "pattern",
                    "\\b(?P<x>the [a-z ]+?) (?:needs|has|have|need) to (?:reach|get to|end up with|go to) (?P<p>[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_WHICH_ARM29R",
                (
                    "pattern",
                    "^(?:i|we) (?:don't|do not) (?:mind|care) which (?:of your arms|arm|robot|of the robots|of you|one of you)(?: (?:does it|does that|takes it|goes|handles it))?\\s*[,;:.]\\s*(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_which_gets28r": (
        "18d3d5b247028f4a",
        ((), ("that", "which"), False),
        (),
    ),
    "hltl.grounding._normalise3:_which_kind30r": (
        "215a9483e56fc935",
        ((), (" the one for ", " which "), True),
        (
            (
                "_WHICHEVER_FIRST30R",
                (
                    "pattern",
                    "^whichever (?P<x>[a-z]+)(?:'s| is) (?P<how>nearer|closer|nearest|closest|handier|easier to reach)(?: (?:to )?(?:your arm|the arm|you|the robot))?\\s*,\\s*that(?:'s| is) the one for (?P<p>[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_WHICH_KIND30R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?:isn't|is not|'s not|doesn't mind|does not mind|doesn't care|does not care)(?: (?:bothered|fussed|fussy|particular))? which (?P<x>[a-z]+)\\s*,\\s*(?P<will>(?:either|any)(?: one)? (?:will do|is fine|'ll do))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_whichever_front31r": (
        "85edf3d5da77f82b",
        ((), ("whichever",), True),
        (
            (
                "_WHICHEVER_FRONT31R",
                (
                    "pattern",
                    "^whichever(?:'s| is) (?P<how>handier|nearer|closer|easier(?: to (?:reach|grab|get))?|nearest|closest)\\s*,\\s*(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?? or (?:the |a |an )?[a-z]+(?: [a-z]+)??)\\s*,\\s*(?P<rest>[^,;:.!?]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_whichever_of30r": (
        "55faca2610b46750",
        ((), (" of the",), True),
        (
            (
                "_WHICHEVER_OF30R",
                (
                    "pattern",
                    "\\b(?P<to>to|for) (?:whichever|either|any)(?: one)? of (?:the (?P<n>two|three)(?: of them)?|them(?: both| two)?|the pair of them|the (?P<m>two|three) of you),\\s*(?P<list>(?:[A-Za-z][\\w ]*?,\\s*)*[A-Za-z][\\w ]*? or [A-Za-z][\\w ]*?)(?=\\s*(?:[.!;]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_whichever_there31r": (
        "321ab6711fa6e03b",
        ((), ("whichever ",), True),
        (
            (
                "_WHICHEVER_THERE31R",
                (
                    "pattern",
                    "^whichever (?P<x>[a-z]+)(?:'s| is) (?:there|here|about|around|left)\\s*,\\s*(?P<rest>[^,;:.!?]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_whose33t": ("49eed6193e7768c7", (("'s ",), (), False), ()),
    "hltl.grounding._normalise3:_will_do_for31r": (
        "4536c2a1b989d533",
        ((), (" for ", "is fine", "will do", "works", "would do"), True),
        (
            (
                "_WILL_DO_BUT31R",
                (
                    "pattern",
                    "^(?P<q>either|any) (?P<x>[a-z]+) (?:will do|would do|is fine|works),?\\s*(?:but|and|only) (?:it's|it is|it'll be|it will be|that's|that is) (?:for|going to) (?P<p>[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_WILL_DO_FOR31R",
                (
                    "pattern",
                    "^(?P<q>either|any) (?P<x>[a-z]+) (?:will do|would do|is fine|works) for (?P<p>[A-Za-z][\\w ]*?)(?=\\s*,)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_wont_mind31r": (
        "1101f8a0f826bfd1",
        ((), (" mind",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise3:_wont_you33t": (
        "0b77df6d998d524b",
        ((), ("won't you ",), True),
        (
            (
                "_DO_VERBS",
                (
                    "value",
                    "'(?:give|hand|pass|bring|take|send|put|place|move|leave|set|drop|deliver)\\\\b'",
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise3:_yes_meant31r": (
        "e139d54bf9699b3f",
        ((), ("that's right", "yeah", "yep", "yes", "yup"), True),
        (
            (
                "_YES_MEANT31R",
                (
                    "pattern",
                    "(?P<lead>[.!]\\s+)(?:yes|yeah|yep|yup|that's right),?\\s+(?P<p>[A-Za-z][\\w ]*?)(?:,?\\s*(?:i (?:did )?mean(?:t)? (?:her|him|them|it)|that's (?:right|who i meant)|(?:she|he)'s the one))?\\s*[.!]?$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise3:_you_pick32r": (
        "783601a210376394",
        (
            (),
            (" let you ", " not ", "don't care ", "don't mind ", "you choose", "you pick", "your "),
            True,
        ),
        (
            (
                "_YOU_PICK32R",
                (
                    "pattern",
                    ",\\s*(?:you pick|you choose|your (?:pick|choice|call)|(?:i'll|i will) let you (?:choose|pick|decide)(?: which (?:goes|one goes) where| who gets (?:which|what))?|(?:i'm|i am) not (?:fussed|bothered|fussy) (?:who (?:ends up with|gets) (?:what|which))|(?:i )?don't mind (?:how|which way(?: round)?|who gets (?:what|which))|(?:i )?don't care (?:how|which way(?: round)?|who gets (?:what|which)))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_after_all_along34r": (
        "8c34db2591940f25",
        ((), (" been after ",), True),
        (
            (
                "_ALL_ALONG34R",
                (
                    "pattern",
                    "\\b(?P<s>she|he)(?:'s| has) been after (?P<x>the [a-z]+(?: [a-z]+)?) all along\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_after_doing37": (
        "6465109aee561a02",
        ((), ("after", "following", "since"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise4:_after_her35r": (
        "6a80e31da038fa73",
        ((), ("after",), False),
        (
            (
                "_AFTER_HER35R",
                (
                    "pattern",
                    ",\\s*after (?P<w>(?:her|his|their) (?:[a-z]+ )?(?:[a-z]+(?:ing|ics)|class|lesson|practice|training|shift|session|match|game|nap|walk|swim|workout|rehearsal|appointment|meeting|exam|lecture|visit|round))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_after_those34t": (
        "8f0fc356f0d7ba60",
        ((), (" after ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_alike34r": (
        "f67ceb03479eddce",
        ((), (" alike",), True),
        (
            (
                "_ALIKE34R",
                (
                    "pattern",
                    "^(?P<head>.*\\bboth\\b.+,\\s*(?:the )?[a-z]+ and (?:the )?[a-z]+) alike(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_also_hers36": (
        "e0cfea21f9ba2515",
        ((), ("again", "also", "likewise"), True),
        (
            (
                "_ALSO_HERS36",
                (
                    "pattern",
                    ",\\s*(?:also|again|likewise) (?P<pron>hers|his|theirs)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_and_for35r": ("5650e338739dd769", ((), ("and for",), False), ()),
    "hltl.grounding._normalise4:_any_arm37r": (
        "c1fd41ba4a187bee",
        ((), (" do ",), True),
        (
            (
                "_ANY_ARM37R",
                (
                    "pattern",
                    "^(?:either|any|whichever|each) (?:arm|robot|hand|one of you|of you|of your arms) (?:can|will|could|may) do (?:it|this|that|the job)\\s*[:;,.]\\s*(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_any_order33r": (
        "52e35b045e755304",
        ((), (" order",), True),
        (
            (
                "_ANY_ORDER33R",
                (
                    "pattern",
                    ",\\s*(?:and )?in (?:whatever|any) order(?: (?:suits you|you like|you want|you fancy|is easiest))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_anything_at_all33r": (
        "7360870a6c6cb940",
        ((), ("anything",), True),
        (
            (
                "_ANYTHING_AT_ALL33R",
                (
                    "pattern",
                    "^anything(?: at all)? for (?P<p>[A-Za-z][\\w ]*?),\\s*(?:just )?(?:the )?one(?: item| thing)?(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_anything_but33r": (
        "3ec77f1490cea180",
        ((), ("anything",), True),
        (
            (
                "_ANYTHING_BUT33R",
                (
                    "pattern",
                    "\\banything(?: at all)?,? (?:(?:but|except|apart from|other than|bar)|as long as it(?:'s not| isn't| is not)) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)(?=\\s*(?:[,;.!]|$|\\s(?:for|to|goes|go|onto|into|on|in)\\b))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_anything_but34r": (
        "57e79062f9f0264c",
        ((), ("anything but ",), True),
        (
            (
                "_ANYTHING_BUT34R",
                (
                    "pattern",
                    "\\b(?P<a>an? [a-z]+),\\s*anything but (?P<x>the [a-z]+ one|the [a-z]+ [a-z]+)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_anything_but35r": (
        "e50ec375f3d9c2e1",
        ((), ("anything",), False),
        (
            (
                "_ANYTHING_BUT35R",
                (
                    "pattern",
                    "^(?P<p>[a-z]+(?: [a-z])?) can have anything (?:but|except|other than) (?P<x>[^,.;!?]+?)(?:,\\s*(?:i'm|i am) not (?:fussed|bothered) (?:what|which))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_apiece35r": (
        "3bb044784049ec7e",
        ((), (" each ", " thing "), True),
        (
            (
                "_APIECE35R",
                (
                    "pattern",
                    "^(?:(?:(?:they|both of them|the two of them)(?:'re| are) to (?:have|get) )?(?:one|a single) thing (?:apiece|each|for each of them)|(?:they|both of them|the two of them) each (?:get|have) (?:a|one|a single) thing)\\s*,\\s*(?=so\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_are_hers34r": (
        "1edddfb91d23e2d1",
        ((), (" of the ",), True),
        (
            (
                "_ARE_HERS34R",
                (
                    "pattern",
                    "^(?P<q>both|all (?:two|three|four)) of the (?P<k>[a-z]+) are (?P<p>[a-z][\\w ]*?)'s,\\s*(?:so )?give (?P<pro>her|him) (?:the pair|both|them|the lot|all of them|the two)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_as_long_as37r": (
        "d703aa570a5e5d96",
        ((), ("as long as", "provided", "so long as"), True),
        (
            (
                "_AS_LONG_AS37R",
                (
                    "pattern",
                    "^(?:go|do it|get it done|do it) (?:whichever|whatever|any|which ever) (?:route|way) (?:suits you|you like|you want|you fancy|works for you|is easiest)(?: best)?,\\s*(?:as long as|so long as|just so long as|provided|provided that) (?P<rest>.+?)(?: in the end| at the end| eventually)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_aside_else35t": (
        "8694840e8ea9c305",
        ((), (" the robot ", "the robot"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_asked_first34t": (
        "8a73aed1007a965a",
        ((), ("the ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_at_table34r": (
        "04bd3833ccbdf032",
        ((), (" table ",), True),
        (
            (
                "_AT_TABLE34R",
                (
                    "pattern",
                    "^the (?P<role>[a-z]+) (?:on|at) table (?:[a-z]+|\\d+),\\s*(?P<p>[a-z][\\w ]*?),\\s*(?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_belongs35r": (
        "04f5474ab51d85e4",
        ((), ("belong",), False),
        (
            (
                "_BELONGS35R",
                (
                    "pattern",
                    "(?P<cue>\\bno),\\s*(?:it|they) (?:belongs?|is|are|'s) (?:to )?(?P<p>[^,.;!?]+?)(?:'s)?,\\s*(?P<v>give|hand|pass|take) (?P<it>it|them) (?:back )?to (?P<pro>her|him)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_better_down34r": (
        "ee265ff340dee381",
        ((), ("better ",), True),
        (
            (
                "_BETTER_DOWN34R",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|sorry|actually|i mean|i meant|or rather|correction),\\s*)better (?:down |up )?(?P<p>on|in|onto|into) the (?P<s>[a-z]+(?: [a-z]+)?)(?: with (?:her|him|them))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_body_state36": (
        "6de55f14d7ffb963",
        ((" ears", " feet", " fingers", " hands", " nose", " toes"), (), False),
        (),
    ),
    "hltl.grounding._normalise4:_both_like34r": (
        "222a5786648d585d",
        ((), ("either ",), True),
        (
            (
                "_BOTH_LIKE34R",
                (
                    "pattern",
                    "^(?P<head>either .+?),\\s*(?:they|they'd) both (?:like|love|enjoy|want|read|use)\\b(?P<why>[^,;.!]*)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_both_named35r": (
        "e15d0a6283b0f1b9",
        ((), (" one and the ",), True),
        (
            (
                "_BOTH_NAMED35R",
                (
                    "pattern",
                    "^(?P<head>both (?P<k>[a-z]+)),\\s*the (?P<a>[a-z]+) one and the (?P<b>[a-z]+) one,\\s*(?P<v>go|goes)(?: away)? (?P<rest>(?:in|into|on|onto) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_brought_own34r": (
        "ad1bf40a71712ab9",
        ((), ("don't bother with ",), True),
        (
            (
                "_BROUGHT_OWN34R",
                (
                    "pattern",
                    "^(?P<h>don't bother with (?:the )?[a-z]+),\\s*(?:she|he)(?:'s| has) (?:brought|got) (?:a|an|her|his) (?P<w>[a-z]+)(?: with (?:her|him))?,\\s*(?P<rest>just .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_but_flawed33r": (
        "c73603951e419c96",
        ((), ("so not that one",), True),
        (
            (
                "_BUT_FLAWED33R",
                (
                    "pattern",
                    ",\\s*but the (?P<a>[a-z]+) one(?:'s| is| has)(?: got)? (?:a crack|cracked|a chip|chipped|broken|dirty|filthy|leaking|stained)\\s*,\\s*so not that one(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_but_not_on34r": (
        "c1c33eac95e504f7",
        ((), ("not the one ",), True),
        (
            (
                "_BUT_NOT_ON34R",
                (
                    "pattern",
                    "\\bthe (?P<k>[a-z]+),\\s*(?:but )?not the one (?P<p>on|in) the (?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_but_not_those36r": (
        "d552293bbec63c61",
        ((), ("but not ",), True),
        (
            (
                "_BUT_NOT_THOSE36R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?) (?P<v>gets|is getting|has|is having) (?P<x>the [a-z]+(?: [a-z]+)?),?\\s*but not (?P<y>the [a-z]+(?: [a-z]+)?),\\s*(?:those|these|they|that|this|it)(?:'re| are|'s| is) (?:for|going to) (?P<q>[a-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_change_that35r": (
        "08261ab11749edf9",
        ((), ("getting", "to get", "to have"), True),
        (
            (
                "_CHANGE_THAT35R",
                (
                    "pattern",
                    "^(?P<p1>[a-z]+(?: [a-z]+)?) was (?:to get|getting|going to get|meant to get|to have) (?P<x>the [a-z]+(?: [a-z]+)?),\\s*but (?:change that|scratch that|no),\\s*(?P<p2>[a-z]+(?: [a-z]+)?)(?:'s| is) (?P<why>[^,.;!?]+?),\\s*so (?P<pro>him|her)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_choice_follows33r": (
        "d2d3c46f8a4e9ee9",
        ((), (" whichever",), True),
        (
            (
                "_CHOICE_FOLLOWS33R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) (?P<v>would like|wants|needs|is after|'s after) an? (?P<k>[a-z]+)\\.\\s*(?P<a>[a-z]+) or (?P<b>[a-z]+),\\s*(?:just )?(?:grab|pick|take|choose|get|bring) whichever(?: one)?(?:'s| is) (?:nearer|closer|nearest|closest|handier)(?: to you)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_cleft_corrected33s": (
        "480dfa825c0dcdf4",
        ((" the one",), (), True),
        (
            (
                "_CLEFT_CORRECTED33S",
                (
                    "pattern",
                    "(?P<cue>,\\s*(?:no|sorry|i mean|actually|wait|no wait)(?:,\\s*|\\s+))(?P<who>[A-Z][a-z]+(?: [A-Z][a-z]+)?)(?:'s| is) the one(?: (?:who|that))? (?P<rest>[a-z][^,.;!?]*?)(?P<end>[.!]*)\\s*$",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_cleft_isnt37r": (
        "0c2efc677652648a",
        ((), (" should ",), True),
        (
            (
                "_CLEFT_ISNT37R",
                (
                    "pattern",
                    "^it(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)??) (?:that )?(?P<p>[a-z][\\w ]*?) should (?P<v>have|get),\\s*(?P<y>the [a-z]+(?: [a-z]+)?) (?:isn't|is not|'s not) (?P<pro>his|hers)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_cleft_not_then35r": (
        "0d47ec69966f0f2c",
        ((), ("not the ",), True),
        (
            (
                "_CLEFT_NOT_THEN35R",
                (
                    "pattern",
                    "^(?P<c>it(?:'s| is) the [a-z ]+? (?:wants|needs|asked for|would like),\\s*not the [a-z ]+?),\\s*(?P<rest>[^,.;!?]+?(?P<end>\\s*[.!]?))$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_closers34t": (
        "7e076feaeaa18cad",
        (
            (),
            (
                "cheers",
                "got it",
                "i mean ",
                "off you go",
                "thank you",
                "thanks",
                "that is all",
                "that's all of it",
                "that's it",
                "that's the lot",
                "the ",
                "when u can",
            ),
            True,
        ),
        (
            (
                "_CLOSERS34T",
                (
                    "value",
                    "\"off you go|got it|that's all of it|that's it|that is all|that's the lot\"",
                ),
            ),
            (
                "_COURTESY24",
                (
                    "value",
                    "'habari(?: yako| gani)?|jambo|hujambo|sawasdee|sawatdee|sawasdi|dobryi den|dobryy den|dobry den|dobriy den|pryvit|vitayu|selamat (?:pagi|petang|siang|malam|datang)|apa khabar|merhaba|yassou|yassas|geia sou|xin chao|kumusta|kamusta|magandang (?:umaga|hapon|gabi)|namaste|namaskar|salaam|salam|as-?salaamu? alaikum|shalom|hola|bonjour|ciao|konnichiwa|ni hao|kia ora|sawubona|ahoj|asante(?: sana)?|khop khun(?: mak)?|khob khun(?: mak)?|kop khun|diakuiu|dyakuyu|diakuyu|spasibo|terima kasih|salamat|tesekkurler|efharisto|efcharisto|cam on|dhanyavaad|dhanyavad|shukriya|shukran|gracias|merci(?: beaucoup)?|grazie(?: mille)?|danke(?: schon)?|arigato(?: gozaimasu)?|xie xie|obrigado|obrigada|dziekuje|diolch|toda|kiitos|mamnoon|mamnun|khahesh mikonam|terima kasih banyak|makasih|köszönöm|koszonom|köszi|koszi|jó napot(?: kívánok)?|jo napot(?: kivanok)?|szia|permisi|sudah|terserah|mas|mbak|bless up|big up|respect|one love|dobrý den|dobry den|děkuji|dekuji|děkuju|dekuju|bună ziua|buna ziua|bună|mulțumesc|mulţumesc|multumesc|mersi(?: mult)?|vanakkam|vanakam|nandri|nanri|chale|medaase|akwaaba|gamarjoba(?:t)?|(?:didi )?madloba|genatsvale|nakhvamdis|labas(?: rytas| vakaras)?|laba diena|ačiū(?: labai)?|aciu(?: labai)?|tena yistilign|tena yistiligne|tena yistilgn|selam(?: new)?|(?:betam )?(?:ameseginalehu|amesegnalehu|ameseginalew)|ayubowan|(?:bohoma )?(?:sthuthi|sthuthiy|stuthi|isthuthi|istuti)|labdien|paldies|sveiki|tere|aitäh|aitah|tänan|tanan|barev(?: dzez)?|shnorhakalutyun|sağ ?ol|sag ?ol|çox sağ ?ol|chox sag ?ol|hvala(?: lijepa| puno| vam)?|zdravo|dobar dan|dzień dobry|dzien dobry|cześć|czesc|dziękuję|privet|zdravstvuyte|blagodaryu|blagodarya|tack(?: så mycket| sa mycket)?|takk|tusen takk|mange tak|hej|hei|dank je(?: wel)?|dank u(?: wel)?|bedankt|goedemorgen|goedemiddag|annyeonghaseyo|annyeong|kamsahamnida|gamsahamnida|gomawo|mingalaba|mingalarba|dhanyabad|dhonnobad|nomoskar|sat sri akal|sannu|na gode|daalu|ndewo|ngiyabonga|siyabonga|enkosi|mahalo(?: nui)?|aloha|toda raba|marhaba|ahlan(?: wa sahlan)?|teşekkür ederim|tesekkur ederim|olá|bom dia|buenos (?:días|dias)|buenas tardes|muchas gracias|e kaaro|e kaasan|e kaale|e ku aaro|e ku irole|e se(?: gan| o)?|o se(?: gan| o)?|ole hyvä|ole hyva|moi|kiitti|faleminderit|grazas|moitas grazas|meur ras|zikomo(?: kwambiri)?|mesi(?: anpil)?|malo aupito|mālō aupito|sulpayki|añay|anay|tenkyu(?: tru)?|kadrinchey(?: la)?|kadrin chhe(?: la)?|natotela(?: sana)?|ua tsaug(?: ntau)?|ke a leboga|kea leboga|kealeboga|eskerrik asko|mila esker|milesker|gràcies|gracies|moltes gràcies|moltes gracies|ďakujem(?: pekne)?|dakujem(?: pekne)?|vďaka|vdaka|bless you|amen(?: to that)?|inshallah|mashallah|pole pole|innit|khrap|khrub|krap|krub|hor|kha|lah|leh|lor|meh|opo|paa|sha|ah|ja|la|po|o'",
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_closing_remarks36": (
        "0deb0c907299c027",
        ((), (" the one ", "clock", "day", "night", "shift", "time", "week"), True),
        (
            (
                "_BACK_FROM36",
                (
                    "pattern",
                    "(?P<lead>\\s+(?:(?:thx|thanks|ta|cheers),?\\s+)?|,\\s*)(?P<pron>he|she)(?:'s|s| is) the one (?:just )?(?:back from|home from|in from|off to|back off) (?P<what>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_corrected_away33r": (
        "e9ad33f39427e685",
        ((), ("done with", "finished with", "no longer", "not", "off", "too"), True),
        (
            (
                "_CORRECTED_AWAY33R",
                (
                    "pattern",
                    "^(?P<head>.+?\\b(?:no|sorry|oops|i mean|i meant),?\\s+(?:i mean\\s+|i meant\\s+)?(?:to )?(?P<q>[A-Za-z][\\w ]*?)),\\s*(?P<p>[A-Za-z][\\w ]*?)(?:'s| is) (?P<why>(?:too|not|no longer|off|done with|finished with)\\b[a-z' ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_corrected_place_why34r": (
        "dcdd47db380dfcce",
        ((), ("the ",), True),
        (
            (
                "_CORRECTED_PLACE_WHY34R",
                (
                    "pattern",
                    "^(?P<head>.+\\b(?:no|sorry|actually),\\s*(?:on |in )?the (?P<s2>[a-z]+(?: [a-z]+)?)),\\s*the (?P<s1>[a-z]+(?: [a-z]+)?)(?:'s| is) (?P<why>[a-z ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_correction_cue33r": (
        "60c65e2d371169d5",
        ((), (" my mistake", " not ", " that wrong", "correction from ", "wrong way round"), True),
        (
            (
                "_CORRECTION_CUE33R",
                (
                    "pattern",
                    "[,.]\\s*(?:(?:oh|ah|er|um),? )?(?:hang (?:about|on),? i (?:got|had) that wrong|(?:hmm|hm|erm|um),? no,? my mistake|(?:a )?correction from (?:the )?[a-z]+(?: [a-z]+)?|no,? (?P<way>wrong way round|the wrong way round)|(?:no|well|ah|er|um|sorry),? not (?P<x>(?:the )?[A-Za-z]+(?: [A-Za-z]+)?))\\s*,\\s*(?P<fix>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_counted_state35r": (
        "a6fbc3f1624f07f4",
        ((), ("them",), True),
        (
            (
                "_COUNTED_STATE35R",
                (
                    "pattern",
                    "^(?:those|these|the|both) (?P<n>two|three|four) (?P<k>[a-z]+) (?:are|'re) (?P<adj>[a-z]+)\\s*,\\s*(?:so )?(?P<v>put|pop|stick|place|set|take|bring|move) (?P<them>the pair of them|both of them|them|all (?:two|three|four) of them|the (?:two|three|four) of them) (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_counted_want34r": (
        "b2bf83e1a45fb648",
        ((), (" to ",), True),
        (
            (
                "_COUNTED_WANT34R",
                (
                    "pattern",
                    "^(?P<d>those|the|all|both)(?P<n> two| three| four)?(?P<of> of the)? (?P<k>[a-z]+s) (?:want|need) to (?:go|sit|be|live) (?P<p>on|onto|in|into) ",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_cue_remark33r": (
        "cf8c6e645e40b304",
        ((), ("no,",), True),
        (
            (
                "_CUE_REMARK33R",
                (
                    "pattern",
                    "^(?P<head>[^,;.!?]+?),\\s*(?:oh,? )?no,\\s*(?P<pro>she|he|they)(?:'s| is|'re| are) (?P<why>[a-z' ]+?),\\s*(?P<fix>to [A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_dedication34t": (
        "9a03cbffb3665998",
        ((), (" goes out to ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_does_why36r": (
        "ef51c49b519d4aad",
        ((), (" does",), True),
        (
            (
                "_DOES_WHY36R",
                (
                    "pattern",
                    "^(?P<head>.+?,\\s*(?:scratch that|no|sorry|actually|wait|i mean|no wait),?\\s*(?P<p>[a-z][\\w ]*?) does),\\s*(?P<why>(?P<pro>she|he) (?:won|lost|asked|called|got|paid|bought|earned|came|did)\\b[^,.;!?]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_doesnt_only37r": (
        "fc1be6bb0b69e218",
        ((), (" does",), True),
        (
            (
                "_DOESNT_ONLY37R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?) (?:doesn't|does not) (?P<v>want|need) (?P<x>the [a-z]+(?: [a-z]+)?),\\s*(?:only|just) (?P<y>the [a-z]+(?: [a-z]+)?)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_done_with35s": (
        "207e3b6ee6ee4a1a",
        ((), (" been ", "done", "finished"), True),
        (
            (
                "_DONE_WITH35S",
                (
                    "pattern",
                    "(?:\\s*,\\s*(?:as |since |because )?(?P<who>[A-Za-z][\\w ]*?)(?:'s| is| has| are|'re|'ve| have) (?:finished|done)(?: with)? (?:it|them)|,?\\s+now(?: that)? (?:it|they)(?:'s| has| is|'re| are| have|'ve) been (?:used|finished|emptied|read|done))(?=\\s*[.!]?$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_dont_instead35r": (
        "0b2b1aff3a2bc4ad",
        ((), ("instead",), False),
        (
            (
                "_DONT_INSTEAD35R",
                (
                    "pattern",
                    "^(?:don't|do not) (?P<v>give|hand|pass) (?P<p>[a-z]+(?: [a-z])?) (?P<x>the [a-z]+(?: [a-z]+)?),\\s*(?:(?P<why>[^,.;!?]+?),\\s*)?(?:give|hand|pass) (?P<pro>him|her) (?P<y>the [a-z]+(?: [a-z]+)?) instead(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_drink_in35t": (
        "fef32d8ef7b5d6c4",
        ((), ("'d like", "could do with", "needs", "wants", "would like"), True),
        (
            (
                "_DRINKS35T",
                ("value", "'(?:water|a drink|drink|juice|milk|squash|tea|coffee|a brew|a cuppa)'"),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise4:_each_for_role37r": (
        "9d387715d8471482",
        ((), (" for the ",), True),
        (
            (
                "_EACH_FOR_ROLE37R",
                (
                    "pattern",
                    "^(?:a|one) (?P<k>[a-z]+) (?:each|apiece) for the (?P<role>[a-z]+?)s(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_each_role36r": (
        "4384e60b72bbab62",
        ((), ("each ",), True),
        (
            (
                "_EACH_ROLE36R",
                (
                    "pattern",
                    "^each (?P<role>[a-z]+) (?:gets|is to (?:have|get)|should (?:have|get)|can have|will get) (?:a|one) (?P<k>[a-z]+)\\s*[,:]\\s*(?P<list>[a-z][\\w ]*? the [a-z]+(?: one)?(?:(?:,| and|, and) [a-z][\\w ]*? the [a-z]+(?: one)?)+)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_either_named34r": (
        "26283eb8ecd4f9d7",
        ((), ("either of the ",), True),
        (
            (
                "_EITHER_NAMED34R",
                (
                    "pattern",
                    "\\beither of the (?P<role>[a-z]+),\\s*(?P<p>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+) or (?P<q>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)(?=\\s*[,.!]|\\s*$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_either_person33r": (
        "01545372c900825f",
        ((), (" either ",), True),
        (
            (
                "_EITHER_PERSON33R",
                ("pattern", "\\b(?P<prep>to|for) either (?:person|one)\\b(?! of)", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_either_then_one36r": (
        "c78c1f114ff26a9f",
        ((), ("either ",), True),
        (
            (
                "_EITHER_THEN_ONE36R",
                (
                    "pattern",
                    "^either (?P<p>[a-z][\\w ]*?) or (?P<q>[a-z][\\w ]*?),\\s*(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is) (?:for|going to) (?:one|either) of (?:them|the two)(?P<end>\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_every_counted33r": (
        "d8e148583df525c5",
        ((), ("every ",), True),
        (
            (
                "_EVERY_COUNTED33R",
                (
                    "pattern",
                    "\\b(?P<every>every (?P<single>single )?(?P<kind>[a-z]+))(?P<here> here| in the place| in the room| in sight)?(?P<mid>[^,;.!?]*?)(?P<count>,\\s*all (?P<n>two|three|four|five|six)(?: of them)?)(?:,(?=\\s*[a-z]))?(?=\\s*(?:[,.;!]|$|[a-z]))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_every_included37r": (
        "e7e6897be3e25a1e",
        ((), (" one included", "including the "), True),
        (
            (
                "_EVERY_INCLUDED37R",
                (
                    "pattern",
                    "\\b(?P<every>every|all the) (?P<k>[a-z]+?)(?P<pl>es|s)?(?: in the (?:place|room|building))?,\\s*(?:(?:the )?(?P<a>[a-z]+) one included|including the (?P<b>[a-z]+) one),\\s*",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_every_last37r": (
        "287e207123003678",
        ((), ("every last ",), True),
        (
            (
                "_EVERY_LAST37R",
                (
                    "pattern",
                    "\\bevery last (?:thing|item|one of them|bit)(?: (?:you've|you have|we've|we have) got(?: (?:there|here|about))?| (?:here|there|about))?(?=\\s+(?:is|goes|should|can|needs)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_except_commas37r": (
        "8fb2dd7eee49bde4",
        ((), (" the ",), True),
        (
            (
                "_EXCEPT_COMMAS37R",
                (
                    "pattern",
                    "^(?P<ks>the [a-z]+s),\\s*(?P<ex>(?:except|apart from|but not|bar) the [a-z]+ one),\\s*(?=(?:go|goes|should go|want|need|belong)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_excluded_reason33r": (
        "d63b8c19a3be7ade",
        ((), ("not ",), True),
        (
            (
                "_EXCLUDED_REASON33R",
                (
                    "pattern",
                    "\\bnot (?:the )?[a-z]+(?: one)?(?P<cut>,\\s*(?P<pro>she|he|they) (?:says|said|reckons|thinks|finds) (?:that (?:colour|color|one|size|kind)|it|that|those) [a-z' ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_final_answer34r": (
        "fd60d58d680ae943",
        ((), ("final answer",), True),
        (
            (
                "_FINAL34R",
                (
                    "pattern",
                    "^(?P<head>.+?\\b(?:no|sorry|actually|i mean|i meant|or rather|correction)\\b.+?),\\s*(?:and )?(?:that's )?(?:my )?final answer(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_first_said34r": (
        "927415a9d851b1dd",
        ((), ("first",), True),
        (
            (
                "_FIRST_SAID34R",
                (
                    "pattern",
                    "^(?:at )?first,? I (?:said|asked for|put) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?),?\\s*but (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_for_said34t": (
        "edb12884b59775d9",
        ((), ("for ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_frames34t": (
        "f1ac6ca39e6810b6",
        ((), (" reckon ", " with ", "for ", "i would like ", "same "), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_free_choice33r": (
        "c5f07e1ba89f0c0a",
        (
            (),
            (
                " am not",
                " are not",
                " aren't",
                " first",
                " is not",
                " isn't",
                " way",
                " who gets wh",
                "'m not",
                "'re not",
                "'s not",
                "atever",
                "depending on wh",
                "ichever",
                "need ",
            ),
            True,
        ),
        (
            (
                "_FREE_CHOICE33R",
                (
                    "pattern",
                    ",\\s*(?:(?:whichever|whatever)(?: one)?(?:'s| is) (?:closer|nearer|nearest|closest|handier|handiest)(?: to (?:hand|you)|(?: to)? (?:your|the) (?:gripper|arm|hand))?|whichever(?: one)? you (?:like|pick|choose|prefer|fancy)|(?:whatever|whichever)(?: one)? you (?:grab|reach|get to|can reach) first|depending on (?:what|which|whichever)(?:'s| is) (?:easiest|nearest|closest|handiest|quickest)(?: to (?:reach|get|grab))?|(?P<who>(?:the [a-z]+(?: [a-z]+)?|he|she|they|i)(?:'s not|'re not|'m not| is not| isn't| are not| aren't| am not) (?:really )?(?:fussy|fussed|bothered|particular)(?: (?:which|what)(?: (?:colour|color|one|size|kind|of them))?)?)|(?:i'll|i will) [a-z]+(?: [a-z]+)? (?:on|with|from|in|into) whichever(?: one)? you (?:pick|choose|use)|(?:i|we) (?:just |only )?need (?:the )?one(?: of them)?(?: out| there| down| up)?(?: for (?:the |my |our )?[a-z]+)?|(?P<share>(?:either|any) way(?: round)? (?:is|'s) (?:fine|ok|okay|good)|you (?:decide|pick|choose) who gets (?:which|what)))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_fronted_every35r": (
        "ca81b34446f3ce24",
        ((), ("every",), False),
        (
            (
                "_FRONTED_EVERY35R",
                (
                    "pattern",
                    "^(?P<open>(?:except(?: for)?|apart from|other than|bar|aside from) [^,.;:!?]+,\\s*[^.;:!?]*?)\\bevery (?:item|thing|object|single thing)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_fronted_rest36r": (
        "b11d20892e3cf3a6",
        ((), ("apart from", "aside from", "bar", "except", "other than"), True),
        (
            (
                "_FRONTED_BUT36R",
                (
                    "pattern",
                    "^(?:except(?: for)?|apart from|other than|bar|barring|aside from) (?:the )?[a-z]+(?: [a-z]+)?,\\s*",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_fronted_you37s": (
        "487728cd74e16335",
        ((), (", ", ", you "), True),
        (
            (
                "_FRONTED_YOU37S",
                (
                    "pattern",
                    "(?:^|(?<=[.!?] ))(?P<x>(?:that|this|the) [a-z' -]+?), you (?:can |could |please )?(?P<verb>bring|give|take|hand|pass|carry|put) (?P<rest>(?:for|to|over to|on|in|onto|into) [^,.;!?]+)",
                    34,
                ),
            ),
            (
                "_NAMED_STATE37S",
                (
                    "pattern",
                    "(?:^|(?<=[.!?] ))(?P<p>[A-Z][\\w]*(?: [A-Z][\\w]*)?), (?P<pro>she|he) (?P<be>is|was|'s)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_full_after36r": (
        "7f4771d10d8ea031",
        ((), ("the ",), True),
        (
            (
                "_FULL_AFTER36R",
                (
                    "pattern",
                    "^(?P<head>.+?(?:in|on|into|onto) (?P<s>the [a-z]+(?: [a-z]+)?),\\s*(?:no|sorry|wait|actually),?\\s*(?:(?:in|on|into|onto) )?(?P<t>the [a-z]+(?: [a-z]+)?)),\\s*(?:sorry,\\s*)?(?P<again>the [a-z]+(?: [a-z]+)?)(?:'s| is) (?:full|busy|taken|in use|cluttered|occupied|wet|dirty|a mess|covered)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_gather35r": (
        "ea1a53827b2d8f52",
        ((), (" and ",), True),
        (
            (
                "_GATHER35R",
                (
                    "pattern",
                    "^(?:gather|collect|round|pick) up (?P<x>[^,.;!?]+?) and (?:drop|put|pop|stick|place|pack) (?:them|it|the lot) (?P<prep>in|into|on|onto) (?P<s>the [a-z]+(?: [a-z]+)?)(?P<rest>(?:[,.;!?].*)?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_gets_handed34r": (
        "8538e7ec130721fd",
        ((), (" gets ",), True),
        (
            (
                "_GETS_HANDED34R",
                (
                    "pattern",
                    "\\b(?P<p>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+) gets (?:handed|passed|given) (?=(?:the|a|an) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_going_out34r": (
        "528ed7c1c3e26418",
        ((), (" things going out",), True),
        (
            (
                "_GOING_OUT34R",
                ("pattern", "^(?P<n>two|three|four) things going out\\s*:\\s*(?P<rest>.+)$", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_got_coming37r": (
        "4344317c3e12e30d",
        ((), (" coming,",), True),
        (
            (
                "_GOT_COMING37R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?)(?:'s| has) got (?P<n>a pair of|a couple of|two|three|four) (?:things|items) coming,\\s*(?P<list>the [a-z ,]+?)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_got_count37s": (
        "abd83e3a9b8bf322",
        ((), ("both", "four", "three", "two"), True),
        (
            (
                "_GOT_COUNT37S",
                (
                    "pattern",
                    "(?:\\s*,\\s*|\\s+)(?:so|and|which means|meaning)\\s+(?P<pro>she|he)(?:'s| has| will have|'ll have)(?: got)? (?P<n>two|three|four|both)(?: (?:of them|things|items|now))?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_got_wrong35r": (
        "457d275d8af43cc7",
        ((), ("wrong",), False),
        (
            (
                "_GOT_WRONG35R",
                (
                    "pattern",
                    "(?P<cue>\\b(?:oops|whoops|sorry|oh|hang on|wait)),\\s*i(?:'ve| have)? (?:gone and )?(?:got|had) (?:it|that|them) wrong,\\s*(?P<p>[^,.;!?]+?)(?:'s| is) the one who (?P<v>ordered|wanted|asked for|wants|needs|needed) (?P<it>it|them)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_greeting_said33s": (
        "693b68c2c6eb479d",
        (
            (),
            (
                "afternoon",
                "all right",
                "alright",
                "evening",
                "good ",
                "hello",
                "hey",
                "hi",
                "hullo",
                "morning",
            ),
            True,
        ),
        (
            (
                "_GREETING33S",
                (
                    "pattern",
                    "^(?:(?:ah|oh|well|right)\\s*,?\\s+)?(?P<said>(?:hello|hi|hiya|hey|hullo|morning|afternoon|evening|good (?:morning|afternoon|evening|day)|alright|all right)\\b[^.!?]*[.!]+)\\s+(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_habit36t": (
        "7a9d632461e0ba7c",
        ((), (" habit",), True),
        (
            ("_HABITS36T", ("value", "'chef|kitchen|workshop|old|bad'")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_had_fill37r": (
        "45dda35735376881",
        ((), (" had ",), True),
        (
            (
                "_HAD_FILL37R",
                (
                    "pattern",
                    ",\\s*(?P<p>[a-z][\\w ]*?)(?:'s| has) had (?P<pro>his|her) fill(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_had_no37s": (
        "03693443cb4dbca9",
        ((), (" no",), True),
        (
            (
                "_HAD_NO37S",
                (
                    "pattern",
                    "\\s*,\\s*(?:(?:and|as|because|cos|since|poor thing)\\s+)?(?P<pro>she|he)(?:'s|\\u2019s| has) (?:had|eaten) (?:no|nothing for) (?:breakfast|lunch|dinner|tea|supper|brunch|food|sleep|break|coffee)(?: (?:yet|today|all day|this morning|since [a-z]+))?(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_handy35r": ("6ee41da7ce3fda34", ((), ("handy",), False), ()),
    "hltl.grounding._normalise4:_hang_about37r": (
        "7c3e511570b4b2fa",
        ((), ("hang about,",), True),
        (
            (
                "_HANG_ABOUT37R",
                (
                    "pattern",
                    ",\\s*hang about,\\s*(?=(?:i mean|i meant|no|sorry|make (?:that|it))\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_has_one34r": (
        "f0e47db380765d5f",
        ((), (" got ",), True),
        (
            (
                "_HAS_ONE34R",
                (
                    "pattern",
                    "(?P<cue>\\b(?:hang on|no|actually|wait|sorry),\\s*)(?P<pro>she|he)(?:'s| has)(?: already)? got (?:one|it)(?: already)?,\\s*(?P<rest>(?:give|hand|pass|take) it .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_has_to35s": (
        "fe67f63711c2914a",
        ((), (" to ",), True),
        (
            (
                "_HAS_TO35S",
                (
                    "pattern",
                    "\\b(?P<obj>(?:the |that |this )?[a-z]+(?: [a-z]+)?) (?:has|have) to (?P<v>be|go|sit)(?P<back> back)? (?P<on>on|onto|in|into) ",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_her_ones36r": (
        "bc1961f33533d2b1",
        ((), (" of ",), True),
        (
            (
                "_HER_ONES36R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?) (?P<v>can have|can take|gets|may have) (?P<any>any one|any|either|one) of (?P<pro>her|his) (?P<k>[a-z]+s)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_hers35r": (
        "57ecfdd44683d0b4",
        ((), ("so the",), False),
        (
            (
                "_HERS35R",
                (
                    "pattern",
                    "(?P<lead>,\\s*so )(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is) (?P<pro>hers|his)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_human_noun36t": (
        "2d30254ae6a35cd6",
        ((), ("human ",), True),
        (
            (
                "_HUMAN_NOUN36T",
                (
                    "pattern",
                    "\\bhuman (?=(?:pyramid|pyramids|chain|chains|tower|towers|shield|error|nature|touch|rights|race|resources|cannonball|statue|statues)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_hyphen_time37s": ("7867e16c9ef05ec8", (("-",), (), False), ()),
    "hltl.grounding._normalise4:_idioms34t": (
        "f3540c0f047a30e0",
        (
            (),
            (
                ", the ",
                "advantage played",
                "breathe in",
                "breathe in,",
                "breathe out",
                "my ",
                "omg",
                "play on!",
                "requires ",
                "slay",
                "the wee ",
                "wishes to have",
            ),
            True,
        ),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_in_the_way35t": (
        "b2cd82b37634bc70",
        ((), ("all over", "blocking", "cluttering", "in the way o", "taking up "), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_instead35r": (
        "694f82867d260a16",
        ((), ("instead",), False),
        (
            (
                "_INSTEAD35R",
                (
                    "pattern",
                    "^(?P<p>[^,;]+?)(?:'s| is) (?P<adj>[a-z]+),\\s*so (?P<rest>.+?),? instead(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_into_they_go33r": (
        "b9fc9260caf404f6",
        ((), ("they go", "with "), True),
        (
            (
                "_INTO_THEY_GO33R",
                (
                    "pattern",
                    "^(?P<x>(?:both|the two|all (?:two|three|four)|the) [a-z]+s) (?:both |all )?(?:want|need|could do with) (?:a )?[a-z]+(?: (?P<why>(?:after|before|from) [a-z ]+?))?\\s*,\\s*(?:so )?(?P<prep>into|in|onto|on) (?P<s>the [a-z ]+?) (?:they go|with (?:them|the pair of them|both of them|the pair|the two of them))(?:,\\s*the (?P<a>[a-z]+) and the (?P<b>[a-z]+))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_isnt_hers36r": (
        "b366aba8f785391e",
        ((), ("'s not", "is not", "isn't"), True),
        (
            (
                "_ISNT_HERS36R",
                (
                    "pattern",
                    "^(?P<x>the [a-z]+(?: [a-z]+)?) (?:isn't|is not|'s not) (?P<p>[a-z][\\w ]*?)'s,\\s*(?:it's|it is) (?P<q>[a-z][\\w ]*?)'s(?:,\\s*(?:so )?(?:take|give|bring|hand) it (?:to|over to) (?P<pro>him|her))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_isnt_on35r": (
        "9fc0826d14e667be",
        ((), ("that is",), True),
        (
            (
                "_ISNT_ON35R",
                (
                    "pattern",
                    "\\bthat (?:isn't|is not) (?:already )?(?:sitting |lying |resting |left )?(?P<p>on|in) (?P<s>the [a-z]+(?: [a-z]+)?)(?P<why>,\\s*(?:she|he|they)(?:'ll| will) know why)?",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_it_says35r": (
        "d4f86e6fa6b9fdb0",
        ((), ("it says",), False),
        (
            (
                "_IT_SAYS35R",
                (
                    "pattern",
                    ",\\s*or,\\s*(?:(?:ugh|er|erm|um|hmm|oh),\\s*)?(?:(?:my|the) notes? (?:are|is|'s) [a-z]+,\\s*)?(?P<x>the [a-z]+(?: [a-z]+)?) it says(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_its_p_who34r": (
        "8e25151bc549733a",
        ((), (" getting ",), True),
        (
            (
                "_ITS_P_WHO34R",
                (
                    "pattern",
                    "^it(?:'s| is) (?P<p>[a-z][\\w ]*?) who(?:'s| is) getting (?P<x>the [a-z]+(?: [a-z]+)?),\\s*not (?P<q>[a-z][\\w ]*?)(?:,\\s*(?P<why>[^,.;!?]+?))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_its_the_x33r": (
        "8c5514bb4cee4791",
        ((), ("it's ",), True),
        (
            (
                "_ITS_THE_X33R",
                (
                    "pattern",
                    "\\b(?:no|sorry|actually),\\s*(?:i mean |i meant )?(?P<said>(?:the )?[a-z]+(?: [a-z]+)?),\\s*it's (?P<x>the [a-z]+(?: [a-z]+)?) (?:that |which )?(?:(?:she|he|they)(?:'s| is|'re| are) after|(?:she|he|they) (?:wants?|needs?|asked for))(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_its_x_wants36r": (
        "911ac01e0fe235d6",
        ((), ("asked for", "is after", "needs", "wants"), True),
        (
            (
                "_ITS_X_WANTS36R",
                (
                    "pattern",
                    ",\\s*(?P<no>no|sorry|wait|actually)(?:,?\\s*(?:hang on|hold on|wait))?,?\\s*it(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)?) (?:that )?(?P<pro>she|he) (?:wants|needs|asked for|is after)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_join_the34r": (
        "28a0b7beafe38ade",
        ((), (" can join the ",), True),
        (
            (
                "_JOIN_THE34R",
                (
                    "pattern",
                    "\\b(?P<x>the (?:two |three )?[a-z]+ (?P<k>[a-z]+)) can join the (?P<a>[a-z]+) one (?P<p>on|in) the (?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_keep_going36": ("223de288ddb424d1", (("going",), (), False), ()),
    "hltl.grounding._normalise4:_keep_losing35r": (
        "e73d4305840ada03",
        ((), ("keep",), False),
        (
            (
                "_KEEP_LOSING35R",
                (
                    "pattern",
                    "(?P<head>\\b(?:no|sorry|actually)\\b.*?),\\s*i keep (?:losing|misplacing|forgetting|dropping) (?:it|them)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_kind_before34s": (
        "dfc8b869aad2ea57",
        ((), ("bite", "drink", "nibble", "refreshment", "snack", "treat"), True),
        (
            (
                "_KIND_BEFORE34S",
                (
                    "pattern",
                    "\\b(?:a|an|some) (?P<kind>snack|drink|bite|nibble|treat|refreshment|bite to eat)\\s*,\\s*(?=(?:the|that|this|those|these) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_late_alone35r": (
        "acac1b7ea85de2b8",
        ((), ("it",), False),
        (
            (
                "_LATE_ALONE35R",
                ("pattern", "^(?:sorry,\\s*)?(?P<said>[^.!?]+)\\.\\s+(?P<rest>\\S.*)$", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_lay_hands34r": (
        "8b9052bb2fddda19",
        ((), ("you can ",), True),
        (
            (
                "_LAY_HANDS34R",
                (
                    "pattern",
                    "\\b(?P<any>any (?:[a-z]+ )?[a-z]+) (?:that )?you can (?:lay|get|put) (?:your )?hands on\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_leave_be35r": (
        "50e1cdde7a700f1e",
        ((), ("leave",), False),
        (
            (
                "_LEAVE_BE35R",
                (
                    "pattern",
                    "^(?P<head>.+?)\\s*(?:,\\s*)?(?:and |but )?leave (?P<x>the [a-z]+(?: [a-z]+)?) (?:be|alone)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_leave_corrected33r": (
        "63086b711fbf168d",
        ((), ("leave ",), True),
        (
            (
                "_LEAVE_CORRECTED33R",
                (
                    "pattern",
                    "\\b(?:i mean|i meant|no|sorry),?\\s+(?P<y>the [a-z]+(?: [a-z]+)?),\\s*(?:and )?leave (?P<x>the [a-z]+(?: [a-z]+)?)(?: where it is| there| alone| be)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_leave_only37r": (
        "3445bf966d8d15b4",
        ((), ("leave ",), True),
        (
            (
                "_LEAVE_ONLY37R",
                (
                    "pattern",
                    "^leave (?P<x>the [a-z]+(?: [a-z]+)??)(?: (?:be|alone|where it is))?,\\s*(?:(?P<p>[a-z][\\w ]*?) (?P<o>only|just) (?P<v>wants|needs) (?P<y>the [a-z]+(?: [a-z]+)?)|it(?:'s| is) (?P<o2>only|just) (?P<y2>the [a-z]+(?: [a-z]+)??) (?:that )?(?P<p2>[a-z][\\w ]*?) (?P<v2>wants|needs))(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_leave_that34r": (
        "7cd42df97c93bc7f",
        ((), ("except the ",), True),
        (
            (
                "_LEAVE_THAT34R",
                (
                    "pattern",
                    "(?P<head>\\bexcept the (?P<a>[a-z]+) one),\\s*leave (?:that|it) (?:on|in) the (?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._normalise4:_leaving_aside34r": (
        "54c73d1f15d69a67",
        ((), ("the rest", "what is left", "what's left", "whatever's left"), True),
        (
            (
                "_LEAVING_ASIDE34R",
                (
                    "pattern",
                    "^(?:leaving|setting|putting|keeping) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:aside|to one side),\\s*(?P<p>[a-z][\\w ]*?) can (?:take|have) (?:what's left|whatever's left|what is left|the rest)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_left_as_was34t": (
        "50ddb7a4313e9801",
        ((), ("leave ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_legal34t": (
        "70e8815e09ce2a2c",
        ((), (" likewise", "hereinafter "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_lesson_on37r": (
        "bef8c5146f5b5aae",
        ((), ("for ",), True),
        (
            (
                "_LESSON_ON37R",
                (
                    "pattern",
                    "\\bfor (?P<pro>her|his|their) (?P<what>lesson|talk|class|lecture|session|presentation|seminar|assembly) (?:on|about) (?P<topic>[a-z]+(?: [a-z]+)?)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_likes_both35r": (
        "76ffff09f79f7d9b",
        ((), (" likes ",), True),
        (
            (
                "_LIKES_BOTH35R",
                (
                    "pattern",
                    "^(?P<p>[a-z]+(?: [a-z]+)?) likes (?:both |the two of )?(?:her|his) (?P<k>[a-z]+s)(?: with (?:her|him))?(?: when (?:she|he) [a-z]+)?,\\s*so (?P<v>put|pop|place|set|stick) (?P<them>the pair of them|both of them|the two of them|them) (?P<rest>(?:in|into|on|onto) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_little_one37s": (
        "30d2b32f9535f367",
        ((), ("the ",), True),
        (
            (
                "_LITTLE_ONE37S",
                (
                    "pattern",
                    "\\bthe (?:little|wee|youngest|smallest) one(?= (?:wants|needs|would like|'d like|is after|'s after|could do with|could use)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_load_with35r": (
        "dfb7e5c1244fae38",
        ((), ("all the ", "every "), True),
        (
            (
                "_LOAD_WITH35R",
                (
                    "pattern",
                    "^load (?P<s>the [a-z]+(?: [a-z]+)?) (?:up )?with (?P<x>every [a-z]+|all the [a-z]+)(?: (?:we've got|we have|we've|there is|there are|in here))?(?:\\s*,\\s*all (?P<n>two|three|four|five|six)\\b)?(?P<rest>(?:[,.;!?].*)?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_lone_one34r": (
        "5fdc601683501bc2",
        ((), (" is the one to ",), True),
        (
            (
                "_LONE_ONE34R",
                (
                    "pattern",
                    "^there(?:'s| is) (?:a lone|a single|only one|just the one|just one|one) (?P<k>[a-z]+)(?: (?:in|on) (?:this|the) (?:cell|room|table|bench|place))?(?: here)?,?\\s*and (?P<p>[a-z][\\w ]*?) is the one to (?:have|get|take) it(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_meant_for35r": (
        "2bbad1c360a67f23",
        ((), ("meant",), False),
        (
            (
                "_MEANT_FOR35R",
                (
                    "pattern",
                    "(?P<said>\\bi meant (?P<x>the [a-z]+(?: [a-z]+)?)) for (?P<pro>her|him)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_meant_to_get34r": (
        "a4dd07c1d2905206",
        ((), ("meant", "supposed"), True),
        (
            (
                "_MEANT34R",
                (
                    "pattern",
                    "\\b(?P<it>it's|it is) (?P<p>[a-z][\\w ]*?) who(?:'s| is) (?:meant|supposed) to (?:get|have|receive) (?P<x>it|them|the [a-z]+(?: [a-z]+)?)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_mind_if36r": (
        "e5802d8bc024c21a",
        ((), (" mind if it",), True),
        (
            (
                "_MIND_IF36R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?) (?:won't|doesn't|wouldn't|will not|does not|would not) mind if it(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)?) or (?P<y>the [a-z]+(?: [a-z]+)?),\\s*(?:so )?(?:just )?(?P<v>bring|give|take|hand) (?P<pro>him|her) whichever(?:'s| is) (?P<adj>closer|nearer|nearest|closest|handier|easier)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_modal_first33s": (
        "e4e9ce02fe0bf484",
        ((), (" and ",), True),
        (
            (
                "_MODAL_FIRST33S",
                (
                    "pattern",
                    "^(?P<mod>could|can|would|will|might)\\s+(?P<subj>(?:the )?[a-z][a-z ]*? and (?:the )?[a-z][a-z ]*?)\\s+(?P<rest>(?:both\\s+)?(?:go|be put|be placed|be moved)\\b.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_n_things_each37r": (
        "1dcdc90e48169400",
        ((), ("items", "things"), True),
        (
            (
                "_N_THINGS_EACH37R",
                (
                    "pattern",
                    "^(?:the )?(?P<n>two|three|four) (?:things|items)(?: here| there)?,\\s*one (?:per person|each|apiece|per head)\\s*:\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_name_unknown37s": (
        "1207ed41b0a95031",
        ((), (" name",), True),
        (
            (
                "_NAME_UNKNOWN37S",
                (
                    "pattern",
                    "\\s*[,;]\\s*(?:(?:and|but|as|because|cos|sorry)\\s+)?i (?:don't|do not|dont|can't|cannot) (?:know|remember|recall) (?:his|her|their|the other (?:one|person|guy|lady|man|woman)'s) names?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_need_it_for34r": (
        "36253bb5a97dc732",
        ((), ("need", "want"), True),
        (
            (
                "_NEED_IT_FOR34R",
                (
                    "pattern",
                    "^(?P<head>.+\\b(?:no|sorry|actually|i mean|i meant|or rather|correction)\\b.+?),\\s*we (?:need|want) (?:it|that|them) (?:for|at|in) (?P<why>[a-z ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_needs_both33r": (
        "3d2357ef30c166de",
        ((), ("both", "the pair", "the two"), True),
        (
            (
                "_NEEDS_BOTH33R",
                (
                    "pattern",
                    ",\\s*(?P<pro>she|he|they)(?:'ll| will|'s going to| is going to)? (?:need|want|use) (?:the two|both|them both|both of them|the pair|the two of them)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_needs_on_it37r": (
        "97a728166dd2f7f2",
        ((), ("either the ",), True),
        (
            (
                "_NEEDS_ON_IT37R",
                (
                    "pattern",
                    "^(?P<s>the [a-z]+(?: [a-z]+)?) needs (?:one|a|an) (?P<k>[a-z]+) (?:on|in) it,\\s*(?P<choice>either the [a-z]+ or the [a-z]+)(?: one)?(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_next_event36t": (
        "3d31f940ff324532",
        ((), ("before the",), True),
        (
            (
                "_NEXT_EVENT36T",
                (
                    "pattern",
                    "(?P<lead>,?\\s+before the) next (?P<noun>[a-z]+)(?P<more>(?: [a-z']+){0,3})(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_no_fuss34r": (
        "418e60ee696e5368",
        ((), ("no fuss,",), True),
        (
            (
                "_NO_FUSS34R",
                ("pattern", "^no fuss,\\s*(?P<rest>(?:nothing else,\\s*)?just .+)$", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_no_good34r": (
        "26401df8ee056b9c",
        ((), ("a different one", "another one", "one of the others"), True),
        (
            (
                "_NO_GOOD34R",
                (
                    "pattern",
                    "^(?P<head>.+?\\ban? (?P<k>[a-z]+))\\.\\s*(?:the )?(?P<a>[a-z]+)(?: one)?(?:'s| is) no good(?: for [a-z ]+?)?,\\s*so (?:one of the others|another one|a different one)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_no_need36r": (
        "c9b9fd80f8460afa",
        ((), ("no need for anything ",), True),
        (
            (
                "_NO_NEED36R",
                (
                    "pattern",
                    "^no need for anything (?:fancy|special|else|more),\\s*(?=(?:just|only) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_no_trouble36t": (
        "f631a8a02a60c193",
        ((), ("bother", "trouble"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_no_wait37r": (
        "6716944d3126f906",
        ((), ("no need to ",), True),
        (
            (
                "_NO_WAIT37R",
                (
                    "pattern",
                    "^no need to (?:wait|hang) (?:about|around|round)(?: for anything| for me)?\\s*[,;:]\\s*(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_no_wait_to34r": (
        "dfb3abbbd6c3bb18",
        ((), (" wait,",), True),
        (
            (
                "_NO_WAIT_TO34R",
                (
                    "pattern",
                    "(?P<head>\\b(?:on|in) the [a-z]+(?: [a-z]+)?),\\s*no,? wait,\\s*(?P<to>to [a-z])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_nobody_else33r": (
        "c2d95a63c650fdb1",
        ((), (" else",), True),
        (
            (
                "_NOBODY_ELSE33R",
                (
                    "pattern",
                    "(?:,\\s*|\\s+)(?:and |but )?(?:to |for )?(?:nobody|no one|no-one|noone) else(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_nobody_without34r": (
        "63eab0d4c3031704",
        ((), (" without",), True),
        (
            (
                "_NOBODY_WITHOUT34R",
                (
                    "pattern",
                    "^(?:nobody|no one|no-one) (?:goes|is going|will go|is left) without(?: anything)?\\s*[:,]\\s*(?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_none_of37r": (
        "b96f6a7b263df22b",
        ((), ("none of ",), True),
        (("_NONE_OF37R", ("pattern", "^none of (?P<x>the [a-z]+),\\s*(?=(?:just|only) )", 34)),),
    ),
    "hltl.grounding._normalise4:_not_first35r": (
        "3560ce0a743d8e12",
        ((), ("not ",), True),
        (
            (
                "_NOT_FIRST35R",
                (
                    "pattern",
                    "^not (?P<x>(?:the )?[a-z]+)\\.\\s*(?P<rest>[^.!?]+?)(?P<tail>\\s*[.!].*)?$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_for_after34r": (
        "fcd7fce5a13f5e27",
        ((), (" after ",), True),
        (
            (
                "_NOT_FOR_AFTER34R",
                (
                    "pattern",
                    "^not (?P<x>the [a-z]+) for (?P<p>[a-z][\\w ]*?),\\s*(?:(?P<pro1>he|she) said so(?: twice)?,\\s*)?(?P<pro>he|she)(?:'s| is) after (?:a packet of |a bag of |some |the )?(?P<y>[a-z]+)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_for_other33r": (
        "3155cec37caa1e2f",
        ((), ("not ",), True),
        (
            (
                "_NOT_FOR_OTHER33R",
                (
                    "pattern",
                    ",\\s*(?:and )?(?:definitely |certainly |absolutely |just )?not (?:for|to) (?P<q>(?:the )?[A-Za-z][\\w ]*?)(?:,\\s*who(?:'s| is) (?P<who>[^,;.!?]+?))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_one_other34r": (
        "48f09fb894de3d58",
        ((), ("the other",), True),
        (
            (
                "_NOT_ONE_OTHER34R",
                (
                    "pattern",
                    "^(?P<head>.+?\\ban? (?P<k>[a-z]+))(?: to [a-z]+(?: on| with)?)?\\.\\s*not the (?P<a>[a-z]+) one,\\s*(?:(?:love|dear|pet|mind),\\s*)?the other(?: one)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_q_one34r": (
        "4a1176b20de7da5d",
        ((), ("is the one ",), True),
        (
            (
                "_NOT_Q_ONE34R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?),\\s*not (?P<q>[a-z][\\w ]*?),\\s*is the one (?:getting|to get|who gets|having) (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_the_one_on33r": (
        "524bcea618c17bd2",
        ((), ("not the one ",), True),
        (
            (
                "_NOT_THE_ONE_ON33R",
                (
                    "pattern",
                    "\\bthe (?P<a>[a-z]+) (?P<k>[a-z]+),\\s*not the one (?:up |down )?(?:on|in) the (?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_the_other33r": (
        "b9f028143169e743",
        ((), ("not the ",), True),
        (
            (
                "_NOT_THE_OTHER33R",
                (
                    "pattern",
                    "\\bthe (?P<a>[a-z]+) (?P<kind>one|[a-z]+)(?P<mind>,\\s*mind)?,\\s*not the (?P<b>[a-z]+)(?: one)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_theirs35r": (
        "e8fb46f6c69553b0",
        (("'s",), (), False),
        (
            (
                "_NOT_THEIRS35R",
                (
                    "pattern",
                    "(?P<head>\\bnot the [a-z]+ one),\\s*(?:that's|that is|it's|it is) (?:the )?(?P<o>[a-z]+)'s(?: and (?:she|he|they)(?:'s| is|'re| are) (?P<w>[a-z ]+?))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_not_these33r": (
        "19076f2494a7e736",
        ((), ("not ",), True),
        (
            (
                "_NOT_THERE33R",
                (
                    "pattern",
                    "^not (?:on|in|onto|into|under) (?:the )?(?P<place>[a-z]+(?: [a-z]+)?),\\s*(?P<where>(?:into|onto|to|in|on) [^,;.!?]+?),\\s*(?P<x>the [a-z ]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_NOT_THESE33R",
                (
                    "pattern",
                    "^(?P<nots>(?:not (?:the |a |an )?[a-z]+(?: [a-z]+)?,\\s*)+)(?P<just>(?:just|only) )?(?P<rest>the .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_nothing_besides37r": (
        "20afd2fbfd0ed643",
        ((), (" bother with anything ", "nothing "), True),
        (
            (
                "_NOTHING_BESIDES37R",
                (
                    "pattern",
                    ",\\s*(?:and )?(?:nothing (?:besides|beyond|on top of|apart from|other than) (?:that|it|this)|(?:don't|do not) bother with anything (?:more|else|other))(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_nothing_fancy34r": (
        "1a69f58808876050",
        ((), ("just ",), True),
        (
            (
                "_NOTHING_FANCY34R",
                (
                    "pattern",
                    "^(?:nothing (?:fancy|else|more),\\s*)?no (?P<n>[a-z]+(?: [a-z]+)?),\\s*(?P<rest>just .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_nothing_for33r": (
        "81c9ae3cf32822c2",
        ((), ("not",), True),
        (
            (
                "_NOTHING_FOR33R",
                (
                    "pattern",
                    "^(?:nothing for|not to|not for) (?P<q>[A-Za-z][\\w ]*?)(?: today| this time| now| for now)?(?:,\\s*(?P<pro>he|she|they)(?:'s| is|'re| are|'ll| will|'d| would) (?:only )?[a-z]+(?: [a-z]+)?)?\\s*[;.]\\s*(?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_of_everything33r": (
        "d46d76b001e6b644",
        ((), ("all of it", "all that", "all the stuff", "all the things", "everything"), True),
        (
            (
                "_OF_EVERYTHING33R",
                (
                    "pattern",
                    "^(?:out )?of (?:everything|all the things|all the stuff|all of it|all that)(?P<mid>(?: [a-z]+){0,4}),\\s*(?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_on_the_water37s": (
        "eb337eb1e08532a3",
        ((), ("out on the",), False),
        (),
    ),
    "hltl.grounding._normalise4:_once_there37s": (
        "9f29fe9aa7bd1926",
        ((), ("once ",), True),
        (
            (
                "_ONCE_THERE37S",
                (
                    "pattern",
                    "\\bonce (?P<what>it's|it is|they're|they are)(?: (?P<both>both|all))? (?:there|in place|on there|in there)\\b(?!,)(?= (?:the|put|place|give|hand|pass|bring|take|[a-z]+ (?:goes|go) ))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_apiece36r": (
        "227603c12409f44b",
        ((), ("one ",), True),
        (("_ONE_APIECE36R", ("pattern", "^one (?:apiece|each)\\s*:\\s*(?=\\S)", 34)),),
    ),
    "hltl.grounding._normalise4:_one_by34r": (
        "a5b7f83ca2bd6457",
        ((), ("the one ",), True),
        (
            (
                "_ONE_BY34R",
                (
                    "pattern",
                    "^(?P<head>.+\\bto (?P<p>[a-z][\\w ]*?)),\\s*the one (?:by|at|near|next to|beside) the (?P<w>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_each_listed33r": (
        "46e469fe501704e1",
        ((), (" for ",), True),
        (
            (
                "_ONE_EACH_LISTED33R",
                (
                    "pattern",
                    "^(?P<head>one (?:each|apiece) for (?P<p>[A-Za-z][\\w ]*?) and (?P<q>[A-Za-z][\\w ]*?)),\\s*(?P<x>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?)(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_for_each34r": (
        "370d551d74db625a",
        ((), ("one for ",), True),
        (
            (
                "_ONE_FOR_EACH34R",
                (
                    "pattern",
                    "^one for (?P<p>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+),\\s*(?:and )?one for (?P<q>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+),\\s*(?:that's|that is|those are|out of) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?) and (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)(?P<tail>\\s*(?:[;,.!].*)?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_of_these33r": (
        "eeb9da3f313f5070",
        ((), ("one of th",), True),
        (
            (
                "_ONE_OF_THESE33R",
                (
                    "pattern",
                    "^(?:just )?one of (?:these|those|them|the two) (?P<to>to|for) (?P<p>[A-Za-z][\\w ]*?),\\s*(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) or (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_one34r": (
        "382ce0f84d0d79f4",
        ((), ("one person",), True),
        (
            (
                "_ONE_ONE34R",
                ("pattern", "^one (?P<k>[a-z]+),\\s*one person\\s*:\\s*(?P<rest>.+)$", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_other37r": (
        "e4478f9e2e6544b5",
        ((), ("give one of the",), True),
        (
            (
                "_ONE_OTHER37R",
                (
                    "pattern",
                    "^give one of (?:them|the two(?: of them)?) (?P<x>the [a-z]+(?: [a-z]+)?),\\s*(?P<p>[a-z][\\w ]*?) or (?P<q>[a-z][\\w ]*?),\\s*and the other(?: one)? (?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_other37s": (
        "8ea97ff9a2154ac1",
        ((), (" for one",), True),
        (
            (
                "_ONE_OTHER37S",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) and (?P<q>[A-Za-z][\\w ]*?)(?: (?:each|both))?(?: (?:get|have|want|need|gets|has))?(?: one [a-z]+(?: each)?)?\\s*[,:;]\\s*(?P<x>(?:the )?[a-z' -]+?) for one\\s*,?\\s*(?:and )?(?P<y>(?:the )?[a-z' -]+?) for (?:the )?other(?: one)?(?:\\s*,\\s*(?:either way|any way|anyway|whichever way|either way round|any which way)(?: (?:is fine|is ok|is okay|also can|can|works|will do|round))?)?\\s*[.!]?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_one_thing_listed36r": (
        "652001f1e8949c53",
        ((), (" or ",), False),
        (),
    ),
    "hltl.grounding._normalise4:_one_whos36r": (
        "df7a0279ab1a5a75",
        ((), (" the one ",), True),
        (
            (
                "_ONE_WHOS36R",
                (
                    "pattern",
                    "^(?P<head>(?:not (?:the )?[a-z]+(?: [a-z]+)?,\\s*)?(?:the )?[a-z]+(?: [a-z]+)?),\\s*(?P<p>[a-z][\\w ]*?)(?:'s| is) the one (?:who's|who is|that's) (?:(?:a bit|really|very|so) )?(?:peckish|hungry|thirsty|starving|famished|parched|cold|freezing|chilly)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_chew36r": (
        "b21dd99352af6514",
        ((), (" only ",), True),
        (
            (
                "_ONLY_CHEW36R",
                (
                    "pattern",
                    ",\\s*(?P<pro>she|he)(?:'ll| will) only (?:chew|lose|drop|break|spill|throw|break|suck) (?:it|them)(?: anyway)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_for37r": (
        "0239d87a0955e08f",
        ((), ("only ",), True),
        (
            (
                "_ONLY_FOR37R",
                (
                    "pattern",
                    "^only (?P<x>the [a-z]+(?: [a-z]+)?) (?P<to>for|to) (?P<p>[a-z][\\w ]*?)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_gets34r": (
        "3d253d3eec7802fd",
        ((), (" gets anything",), True),
        (
            (
                "_ONLY_GETS34R",
                (
                    "pattern",
                    "^only (?P<p>[a-z][\\w ]*?) gets anything(?: today| now| this time)?,\\s*and (?:it's|it is) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_here34r": (
        "192563e6694174ea",
        ((), (" only ",), True),
        (
            (
                "_ONLY_HERE34R",
                (
                    "pattern",
                    "^(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) to (?P<q>[a-z][\\w ]*?),\\s*no,\\s*(?P<p>[a-z][\\w ]*?),\\s*(?:there's|there is) only (?P<pro>her|him) here(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_one34t": (
        "e20c702ffb6d74af",
        ((), ("all of us", "everyone", "the lot", "us all"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_only_one35r": (
        "1106944b19435a93",
        ((), ("only",), False),
        (
            (
                "_ONLY_ONE35R",
                (
                    "pattern",
                    "^(?P<head>[^,.;!?]+),\\s*there(?:'s| is) only (?:the )?one(?: only)?(?:\\s*,\\s*(?:don't worry|no worries|never mind))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_one_got37r": (
        "f820a9ab8798ae83",
        ((), (" the ",), True),
        (
            (
                "_ONLY_ONE_GOT37R",
                (
                    "pattern",
                    "\\b(?P<head>it(?:'s| is) the (?:only|last) one) (?:we've|we have|I've|I have|you've|you have) got( left)?(?=\\s*[.!]?$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_role37s": (
        "ac7e5e9cadb67a82",
        ((), (" only ",), True),
        (
            (
                "_ONLY_ROLE37S",
                (
                    "pattern",
                    "\\s*,\\s*(?:(?:and|cos|because|as|since)\\s+)?(?:he|she|they)(?:'s|\\u2019s|'re| is| are) (?:the|our|my) only (?P<what>[a-z]+(?: [a-z]+)?)(?: (?:we've got|we have|we've|we got|here|left|around|on shift|today|tonight))?(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_to35r": (
        "77c8db84a1b89bb9",
        ((), ("the ",), True),
        (
            (
                "_ONLY_TO35R",
                (
                    "pattern",
                    "^(?:only|just) (?P<x>the [a-z]+(?: [a-z]+)?),\\s*and (?:only|just) (?:to|for) (?P<p>[^,.;!?]+?)(?:,\\s*(?:no other jobs|nothing else|no other tasks)(?: for now)?)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_only_wants35r": (
        "67ea5b63b19b7c86",
        ((), ("wants",), False),
        (
            (
                "_ONLY_WANTS35R",
                (
                    "pattern",
                    "(?P<head>\\b(?:not fussed|not bothered|doesn't mind|don't mind|does not mind) which),\\s*(?:she|he|they) (?:only|just) wants? (?P<w>(?:a|an|some) [a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_onto_with33r": (
        "8794600bc36117b6",
        ((), (" with ",), True),
        (
            (
                "_ONTO_WITH33R",
                (
                    "pattern",
                    "^(?P<prep>onto|into|on to|in to|up onto) (?P<s>the [a-z]+(?: [a-z]+)?) with (?P<x>[^,;:.!?]+?)(?P<end>\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_opening_scene33t": (
        "e6b82910a82032e5",
        (
            (),
            (
                "bring",
                "can",
                "could",
                "get",
                "give",
                "grab",
                "hand",
                "pass",
                "please",
                "pop",
                "put",
                "stick",
                "take",
                "will",
                "would",
            ),
            True,
        ),
        (
            (
                "_OPENING33T",
                (
                    "value",
                    "\"^(?P<lead>(?:(?:sorry|oh|so|well|right|okay|ok)\\\\s*,?\\\\s+)*)(?P<said>(?:the |our |my )?[a-z]+(?: [a-z]+)?(?:'s|'re| is| are) [a-z' ]+?),\\\\s+(?P<rest>(?:(?:so|and)\\\\s+)?(?:could|can|would|will|please|give|hand|pass|bring|take|grab|get|pop|put|stick)\\\\b.*)$\"",
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise4:_opening_state32s": (
        "3639d10128b8217a",
        ((), ("'s", "had", "has", "is", "looks", "seems", "was"), True),
        (
            (
                "_OPENING_STATE32S",
                (
                    "pattern",
                    "^(?P<lead>(?:(?:oh|so|well|right|okay|ok)\\s*,?\\s+)*)(?:poor\\s+)?(?P<who>[A-Za-z][\\w]*(?: [A-Za-z][\\w]*)?)(?P<verb>'s|\\s+(?:is|has|hasn't|has not|was|wasn't|isn't|is not|had|looks|seems))\\b(?P<words>[^.;!?,]*?)(?P<stop>[.;!]+\\s+|,\\s+(?=(?:so\\s+)?(?:could|can|would|will|please|give|hand|pass|bring|take|get|let|pop|put)\\b)|\\s+(?=so\\s+(?:could|can|would|will|please|give|hand|pass|bring|take|get|let|pop|put)\\b))(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_or_was_it37r": (
        "8c6353a9b8b8c237",
        ((), ("or was it ",), True),
        (
            (
                "_OR_WAS_IT37R",
                (
                    "pattern",
                    ",\\s*or was it (?P<a>[a-z][\\w ]*?),\\s*yes,\\s*(?P<b>[a-z][\\w ]*?)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_ordeal37s": (
        "26300d0552053baa",
        ((), (" after ",), True),
        (
            (
                "_ORDEAL37S",
                (
                    "pattern",
                    "\\b(?P<frame>what [A-Za-z][\\w ]*? (?:really |actually |most )?(?:needs|wants|could use|could do with|would like)) after (?P<ordeal>(?:(?:a|an|one|two|three|four|five|six|seven|eight|nine|ten|twelve|\\d+|several|a few|many) (?:hours?|minutes?|days?|weeks?|months?|years?|shifts?|laps?|miles?) of [a-z' -]+?|a (?:long|hard|busy|tough|rough) (?:day|shift|night|week|morning|afternoon|evening|run|walk)(?: of [a-z' -]+?)?|all that)) (?=is )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_over_with_fixed34r": (
        "ba2e132233353508",
        ((), ("over to ",), True),
        (
            (
                "_OVER_WITH_FIXED34R",
                (
                    "pattern",
                    "^over to (?P<p>[a-z][\\w ]*?) with (?P<x>the [a-z]+(?: [a-z]+)?)(?P<rest>,\\s*(?:hmm,\\s*|oh,\\s*)?(?:(?:no|sorry|actually|i mean|i meant|or rather|correction))\\b.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_own35r": (
        "6d716746a2a45835",
        ((), ("own",), False),
        (
            (
                "_OWN35R",
                (
                    "pattern",
                    "^(?P<head>.+?),\\s*(?P<pro>she|he)(?:'s| has)? (?:brought|got|has) (?:(?:her|his) own (?P<a>[a-z]+)|(?P<b>[a-z]+) of (?:her|his) own)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_owner_then34r": (
        "2c181ec2fa1cdd5a",
        ((), ("give", "hand", "pass", "take"), True),
        (
            (
                "_OWNER_THEN34R",
                (
                    "pattern",
                    "^(?P<x>.+?),\\s*(?:that's|that is|is|it's|it is) (?P<p>[a-z][\\w ]*?)'s,\\s*(?P<v>give|hand|pass|take) it(?: to)? (?P<pro>him|her)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_owner_then37s": (
        "b55ce5f1052bbb80",
        ((), (" it ",), True),
        (
            (
                "_OWNER_THEN37S",
                (
                    "pattern",
                    "(?P<x>\\b(?:that|it|this|(?:the|that|this) [a-z' -]+?)) ?(?:'s|\\u2019s| is) (?P<who>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s|\\u2019s)\\s*[,.;]\\s*(?:so\\s+)?(?:(?P<verb>give|hand|take|pass|bring) it (?:back |over |right back )?to (?P<pro>him|her)\\b|(?P<over>take|bring|run|carry) it (?:over|across|round)(?= *(?:[,.;!?]|$)))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_pair_listed34r": (
        "082ead3c11cfbb35",
        ((), ("the pair of ",), True),
        (
            (
                "_PAIR_LISTED34R",
                (
                    "pattern",
                    "\\bthe pair of (?P<k>[a-z]+s)(?=,\\s*(?:the )?[a-z]+ and (?:the )?[a-z]+\\s*[.!]?$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_pair_of37r": (
        "4901025d65dc4816",
        ((), ("the pair of ",), True),
        (
            (
                "_PAIR_OF37R",
                (
                    "pattern",
                    "\\bthe pair of (?P<ks>[a-z]+s)(?=,\\s*the [a-z]+(?: one)? and the [a-z]+(?: one)?,)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_pardon37s": (
        "e5ea40d7f6eeb289",
        (
            (),
            ("come again", "eh", "pardon", "say again", "sorry", "what was that", "what's that"),
            True,
        ),
        (
            (
                "_PARDON37S",
                (
                    "pattern",
                    "^(?:(?:pardon|sorry|come again|what was that|eh|what's that|say again)\\s*\\?\\s*)+(?:(?:speak up|say (?:that|it) again|a bit louder|louder)(?: a (?:bit|touch|little))?(?:,? please)?(?P<aside>,[^.!?]*)?[.!]\\s*)?",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_people_in36t": (
        "04c784dcc16f1ed1",
        ((), ("'re", "are"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_people_things36r": (
        "d2226ebd43728422",
        ((), ("items", "things"), True),
        (
            (
                "_PEOPLE_THINGS36R",
                (
                    "pattern",
                    "^(?P<n>two|three|four) (?:people|persons),\\s*(?P<m>two|three|four) (?:things|items)\\s*:\\s*(?P<rest>.+?)(?:,\\s*(?:and )?(?:hand|give|pass) (?:them|those) (?:over|out|round))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_pick_whichever34r": (
        "1c0ade549d541752",
        ((), ("pick ",), True),
        (
            (
                "_PICK34R",
                (
                    "pattern",
                    "(?P<head>\\bor\\b.+?),\\s*(?:just )?pick (?:whichever|either|any)(?: one)?(?: you (?:like|want|fancy|prefer))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_pirate34t": (
        "488dd0e9d0fd0444",
        ((), (" treasures", "arr", "cap'n", "hearties", "matey"), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_place_better34r": (
        "bd3100190c0495dc",
        ((), (" the ",), True),
        (
            (
                "_BETTER34R",
                (
                    "pattern",
                    "^(?P<head>.+?\\b(?:no|sorry|actually|i mean|i meant|or rather|correction),\\s*)(?P<p>on|in|onto|into) the (?P<s>[a-z]+(?: [a-z]+)?) (?:is|would be|'d be|will be) (?:better|best)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_placed_then34r": (
        "fdf42aef28070809",
        ((), ("the ",), True),
        (
            (
                "_PLACED_THEN34R",
                (
                    "pattern",
                    "^(?P<x>(?:the )?[a-z]+(?: (?!up\\b|down\\b)[a-z]+)?) (?:up |down )?(?P<p>on|in|onto|into) (?P<s>the [a-z]+(?: [a-z]+)?)(?P<cue>,\\s*(?:(?:actually|hmm|oh|er|um),?\\s*)?(?:no|sorry|wait|actually|hang on|hold on)\\b,?\\s*(?:i meant )?(?:give|hand|pass|take|bring) (?:them|it) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_pronoun_take35r": (
        "64c024f39a315987",
        ((), (" can take ",), False),
        (),
    ),
    "hltl.grounding._normalise4:_rather_after35r": (
        "654ac97b62b63c21",
        ((), ("rather",), False),
        (
            (
                "_RATHER_AFTER35R",
                (
                    "pattern",
                    "^(?P<head>[^.!?]+)[.!]\\s*(?:(?:er|erm|um|hmm|oh),?\\s*)?(?:hold on|hang on|wait),\\s*(?P<pro>she|he)(?:'d| would) rather have (?P<x>the [a-z]+(?: [a-z]+)?)(?:,\\s*go with (?:that|it|that one))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_rather_have35r": (
        "c8a6f62ca5f982ae",
        ((), (" would ",), True),
        (
            (
                "_RATHER_HAVE35R",
                (
                    "pattern",
                    "(?P<cue>\\bno),\\s*(?P<p>[^,.;!?]+?) would (?:rather|prefer to) have (?P<it>it|them)(?: in (?:her|his|their) hands?)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_rather_order34r": (
        "2a6388a67a947735",
        ((), (" and then ",), True),
        (
            (
                "_RATHER_ORDER34R",
                (
                    "pattern",
                    "^(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) and then (?P<y>(?:the )?[a-z]+(?: [a-z]+)?) to (?P<p>[a-z][\\w ]*?),\\s*or rather (?P<y2>(?:the )?[a-z]+(?: [a-z]+)?) first,? and then (?P<x2>(?:the )?[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_rather_person35r": (
        "de727ca1ba3549be",
        ((), ("person",), False),
        (
            (
                "_RATHER_PERSON35R",
                (
                    "pattern",
                    "\\b(?P<prep>to|for) (?P<p1>person [a-z])\\s*,\\s*(?:or rather|no|sorry|i mean),?\\s+(?P<p2>person [a-z]|[a-z]+)(?:\\s*,\\s*i (?:keep|always) (?:mixing|getting) them (?:up|mixed up|muddled))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_really_mind35r": (
        "9d41557d30a17e5c",
        ((), ("mind which",), False),
        (),
    ),
    "hltl.grounding._normalise4:_reason_for_change34t": (
        "aeab8575a74b7a7c",
        (
            (),
            (
                " on the brain",
                "can't stand",
                "doesn't like",
                "don't like",
                "everything you've got there",
                "hate",
                "is allergic to",
                "isn't keen on",
            ),
            True,
        ),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_reasons_said34t": (
        "ee7963d3390ec161",
        ((), (" because ", " own one ", "'s hands"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_remark_places34t": (
        "0a37e90280960eb0",
        ((), ("don't mind me", "here ", "ith the others"), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_reported_fix34t": (
        "8e383fb31d488ad4",
        ((), ("correction",), False),
        (),
    ),
    "hltl.grounding._normalise4:_reported_want34t": (
        "d79bd42fa1dd7d40",
        ((), ("reckons", "said", "says", "tells me", "thinks"), True),
        (
            (
                "_REPORTED34T",
                (
                    "value",
                    '"(?P<lead>^|[.!;]\\\\s+|,\\\\s*(?:(?:oh|and|oh and),?\\\\s+)*)(?P<p>[a-z][\\\\w ]*?) (?:says|said|reckons|thinks|tells me)(?: that)? (?P<pro>he|she|they)(?P<verb>(?:\'d| would) (?:love|like)| wants| needs| fancies)\\\\b"',
                ),
            ),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_restated37r": (
        "ad7176d5072f20d1",
        (
            (),
            (
                " for ",
                " should ",
                " there",
                "'s having",
                "asked ",
                "gets",
                "is having",
                "it was ",
                "meant",
                "needed",
                "needs",
                "should get",
                "should have",
                "the ",
                "wanted",
                "wants",
                "was after",
            ),
            True,
        ),
        (
            (
                "_RESTATED37R",
                (
                    "pattern",
                    ",\\s*(?P<cues>(?:(?:or |oh )?no|sorry|correction|my mistake|my bad|oh dear|oops|whoops|wait|hang on|hold on|hang about|actually|what am i saying)(?:,?\\s*(?:(?:or |oh )?no|sorry|correction|my mistake|my bad|oh dear|oops|whoops|wait|hang on|hold on|hang about|actually|what am i saying))*),\\s*(?:there's no (?P<gone>[a-z][\\w ]*?) here,\\s*)?(?:(?:it|that|they) should (?:be|go to|be for) (?P<p1>[a-z][\\w ]*?)|(?P<pro2>it's|it is|they're|they are) for (?P<p2>[a-z][\\w ]*?)|(?P<p3>[a-z][\\w ]*?) (?:gets|should get|should have|is having|'s having) (?:it|them)|(?P<x1>the [a-z]+(?: [a-z]+)?) (?:goes|should go|belongs) there|it (?:goes|should go|belongs) (?:on|in|onto|into) (?P<s1>the [a-z]+(?: [a-z]+)?)|it was (?P<x2>the [a-z]+(?: [a-z]+)?) (?P<pro>he|she) (?:asked (?:me )?for|wanted|meant)|(?P<pro3>he|she) (?:wanted|wants|asked (?:me )?for|meant|needs|needed|was after) (?P<x3>the [a-z]+(?: [a-z]+)?))(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_said_again36": (
        "ff85d5004ba5f6fb",
        ((), ("fancies", "likewise", "needs", "wants", "would like"), True),
        (
            (
                "_STATE_WANTS36",
                (
                    "pattern",
                    "^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| is) (?:thirsty|hungry|starving|peckish|parched|famished|cold|freezing|tired|shattered) (?P<pron>he|she) (?P<v>wants|needs|would like|fancies)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_said_better34r": (
        "ca718fdbf9560132",
        ((), (" better,",), True),
        (
            (
                "_SAID_BETTER34R",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|sorry|actually),\\s*)(?:the )?(?P<s>[a-z]+(?: [a-z]+)?)(?:'s| is| would be) better,\\s*(?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_said_object34s": (
        "ae65910699b3b911",
        ((), (" said ",), True),
        (
            (
                "_SAID_OBJECT34S",
                (
                    "pattern",
                    "(?P<lead>,\\s*)(?P<who>he|she|they) said (?:the )?(?P<what>[a-z]+(?: [a-z]+)?)(?=\\s*(?:[,.!;]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_said_wanted36t": (
        "1f3f8be3aed3bbc7",
        ((), (" said ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_same_van36r": (
        "453d2397bc929398",
        ((), (" the same ",), True),
        (
            (
                "_SAME_VAN36R",
                (
                    "pattern",
                    ",\\s*(?:the whole lot|the lot|they|they're all|they are all|all of them|it all)(?:'s| is| are|'re)? (?:all )?(?:for|going (?:on|in|out on)|going to) the same (?P<what>[a-z]+)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_says_needs37s": (
        "969c3bcd4fdc9fca",
        ((), ("could do with", "could use", "is missing", "lacks", "needs", "wants"), True),
        (
            (
                "_SAYS_NEEDS37S",
                (
                    "pattern",
                    "\\s*,\\s*(?:(?:and|cos|because|as|since)\\s+)?(?:he|she|they) (?:says|said|reckons|thinks) (?:that )?(?P<thing>(?:the|his|her|their|my|our) [a-z]+(?: [a-z]+)?) (?:needs|wants|could use|could do with|is missing|lacks) (?:it|them|some|some more|a bit|a bit more|more)(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_says_will_do36r": (
        "d3e7e509d71b5380",
        ((), (" says ",), True),
        (
            (
                "_SAYS_WILL_DO36R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?) says (?P<x>(?:either|any) (?:one of the )?[a-z]+) (?:will|would) do(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_she_said34r": (
        "3a36e3310f055492",
        ((), (" said ",), True),
        (
            (
                "_SHE_SAID34R",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|sorry|wait),\\s*)(?:she|he|they) said (?P<a>[a-z]+),\\s*(?P<rest>the (?P=a) [a-z]+)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_singlish34t": (
        "58d214dc3b073fe2",
        ((), ("ah", "eh", "or"), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_sitting37s": (
        "7c00b4dde7fe3228",
        ((), ("'d like", "likes", "needs", "not ", "prefers", "wants", "would like"), True),
        (
            (
                "_NOT_THERE37S",
                (
                    "pattern",
                    ",\\s*(?:and )?not (?:(?:hidden|tucked|shoved|stuck|put|left|lost|buried)(?: away)? )?(?:in|on|under|inside|into|in with) (?:a|an|some|the) (?P<w>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_SITTING37S",
                (
                    "pattern",
                    "\\b(?P<want>wants|would like|'d like|likes|needs|prefers) (?P<x>the [a-z' -]+?) (?:sitting|sat|standing|stood|lying|kept|resting) (?P<on>on|in|by|next to) (?P<s>the [a-z' -]+?)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_sized37s": (
        "6bd88ae174cf99d5",
        ((), ("mid", "size"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._normalise4:_so_instead33r": (
        "b3602dbf584c2900",
        ((), (" instead",), True),
        (
            (
                "_SO_INSTEAD33R",
                (
                    "pattern",
                    "^(?P<head>[^,;.!?]+?),\\s*(?:oh|ah|hmm),\\s*(?P<pro>she|he|they) (?P<why>[a-z' ]+?),\\s*so (?P<x>the [a-z]+ one|the [a-z]+ [a-z]+) instead(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_so_taking33r": (
        "646f6469ab8d4151",
        ((), (" taking ",), True),
        (
            (
                "_SO_TAKING33R",
                (
                    "pattern",
                    "^(?P<lead>(?P<p>[A-Za-z][\\w ]*?)(?:'s| is) [a-z][a-z' ]*?,\\s*so )(?P<pro>he|she)(?:'s| is) taking (?P<x>(?:both,?\\s*)?[^,;:.!?]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_something_for34r": (
        "31455c27a406d412",
        ((), ("something",), True),
        (
            (
                "_SOMETHING_FOR34R",
                (
                    "pattern",
                    "^something(?: to (?:eat|drink|read|nibble on|snack on|play with))? for (?P<p>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+),\\s*(?:either )?(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) or (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)(?P<rest>\\s*(?:[,.!].*)?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_something_for37r": (
        "f02e4ec9ccc0aaff",
        ((), ("a thing", "one thing", "something"), True),
        (
            (
                "_SOMETHING_FOR37R",
                (
                    "pattern",
                    "^there(?:'s| is) (?:something|one thing|a thing) (?:for|going to) (?P<q>both|each|all) (?:of )?them(?:,\\s*mind)?\\s*:\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_sorry_excuse34s": (
        "1933b37fc2a05b3c",
        ((), ("sorry",), True),
        (
            (
                "_SORRY_EXCUSE34S",
                (
                    "pattern",
                    "^(?P<sorry>(?:so )?sorry),?\\s+(?P<why>[a-z' -]+?)\\s*,\\s*(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_sort_out37s": (
        "6b7b478219f8980a",
        ((), ("sort ",), True),
        (
            (
                "_SORT_OUT37S",
                (
                    "pattern",
                    "(?:(?<=[.!?;]) |^)(?:(?:could|can|would|will) you |please )?sort (?:it|them|that|this|those|these|them all|it all|that lot|everything) out(?: for (?:me|us))?(?:,? (?:would you|will you|could you|can you|please|thanks|cheers|ta))?\\s*[.!?]?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_sorted_first34t": (
        "9507963bf849ccfa",
        ((), (" sorted", "priority is "), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_speaker_remarks": (
        "83c89eaafb155a2c",
        (
            (),
            (
                "!",
                "chef",
                "force of",
                "have a",
                "hope",
                "i",
                "me",
                "my",
                "old",
                "we",
                "workshop",
                "you",
            ),
            True,
        ),
        (
            (
                "_REMARK_OPEN",
                (
                    "pattern",
                    "\\b(?:i|i'm|i've|i'll|i'd|im|ive|my|me|we|we're|we've|you|you're|you've|your|hope|hoping|have a|force of|old|chef|kitchen|workshop)\\b|!",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_split_between34r": (
        "bd575c5df6de7a70",
        ((), (" between the",), True),
        (
            (
                "_SPLIT_BETWEEN34R",
                (
                    "pattern",
                    "^split the (?P<n>two|three|four) (?:things|items) between (?:them|the two of them),\\s*(?:one (?:apiece|each),\\s*)?with (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_split_so34r": (
        "ebfa32880e22a9d6",
        ((), ("split ",), True),
        (
            (
                "_SPLIT_SO34R",
                (
                    "pattern",
                    "^split (?:it|them|things|everything) up so(?: that)? (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_state_here36r": (
        "1dd05a1322a76a4e",
        ((), ("the ",), True),
        (
            (
                "_STATE_HERE36R",
                (
                    "pattern",
                    ",\\s*(?P<what>the [a-z]+)(?:'s| is) (?:off|out|down|broken|bust|playing up|not working|on the blink)(?: again)?(?: (?:on|at) this (?:side|end)| in here| over here| today)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_state_run_on35s": (
        "bbf0ec5cf4eb0388",
        ((), ("bring", "fetch", "give", "hand", "pass", "take"), True),
        (
            (
                "_STATE_RUN_ON35S",
                (
                    "pattern",
                    "^(?P<who>[a-z]+(?: [a-z]+)?)(?P<state>(?:'s| is| was)(?: been)? [a-z' ]+?) (?P<req>(?:give|hand|pass|bring|take|fetch) (?:him|her|them)\\b[^,.;!?]*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_stays_but36r": (
        "f84f620378d26906",
        ((), (" stays ",), True),
        (
            (
                "_STAYS_BUT36R",
                (
                    "pattern",
                    "^(?P<x>the (?P<adj>[a-z]+) (?P<k>[a-z]+)) stays (?:put|where it is|as it is)(?: (?:on|in) (?P<s>the [a-z]+(?: [a-z]+)?))?,\\s*but (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_stays_other33r": (
        "a5fcd109383d749b",
        ((), (" gets the other", "but leave the one "), True),
        (
            (
                "_STAYS_OTHER33R",
                (
                    "pattern",
                    "^(?:the (?P<k>[a-z]+) (?:on|in) the (?P<s>[a-z]+(?: [a-z]+)?) stays (?:there|put|where it is)\\s*[;,.]\\s*(?P<p>[A-Za-z][\\w ]*?) gets the other(?: one)?|(?P<p2>[A-Za-z][\\w ]*?) (?:wants|needs|would like) an? (?P<k2>[a-z]+),\\s*but leave the one (?:on|in) the (?P<s2>[a-z]+(?: [a-z]+)?) (?:where it is|there|alone) and give (?:her|him|them) the other(?: one)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_stays_put34r": (
        "1f6d7823d968803f",
        ((), (" stays ",), True),
        (
            (
                "_STAYS_PUT34R",
                (
                    "pattern",
                    "^(?P<head>.+?)(?:,| and|;)\\s*(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) stays (?:where it is|put|as it is)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_still_need34r": (
        "104f6731a2d7cede",
        ((), ("need ",), True),
        (
            (
                "_STILL_NEED34R",
                (
                    "pattern",
                    "(?P<head>\\b(?:bar|except|apart from|but|other than|minus|not) [^,]+?),\\s*I (?:still |'ll )?need (?:those|them|that|it|these)(?: still| later)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_straight_with_it34r": (
        "a65dde96ac8a9c1e",
        ((), (" with it",), True),
        (
            (
                "_STRAIGHT_WITH_IT34R",
                (
                    "pattern",
                    "^(?P<head>.+?)\\s*(?:—|–|,)\\s*(?P<cue>actually|no|sorry),\\s*(?:on second thoughts?,\\s*)?(?:straight |right )?to (?P<p>[a-z][\\w ]*?) with it(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_surface_for34r": (
        "f823dec851d8cbcb",
        ((), (" for ",), True),
        (
            (
                "_SURFACE_FOR34R",
                (
                    "pattern",
                    "^(?P<s>[a-z]+(?: [a-z]+)?) for (?P<x>the [a-z]+(?: [a-z]+)?),\\s*(?:please,\\s*)?(?:or )?no,\\s*(?:(?:better still|even better|better yet),\\s*)?(?:straight |right )?(?P<rest>(?:to|on|onto|in|into) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_swap_order34r": (
        "819c18e508295fca",
        ((), ("swap the order",), True),
        (
            (
                "_SWAP_ORDER34R",
                (
                    "pattern",
                    "^(?P<a>[^;,]+?),\\s*then (?P<b>[^;,]+?);\\s*(?:no,\\s*)?(?:hang on,\\s*|wait,\\s*)?swap the order(?: round| around| over)?,\\s*(?P<y>[^,]+?) first,? and (?P<x>[^,]+?) after(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_takes_off35r": ("080905e026e50b8c", ((), (" takes ",), False), ()),
    "hltl.grounding._normalise4:_target_for34t": (
        "bad343d0a23f9766",
        ((), (" for ", "actually", "instead", "no", "rather", "sorry", "wait"), True),
        (
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
            ("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),
        ),
    ),
    "hltl.grounding._normalise4:_task_had37s": (
        "1a2f4ed82ae7c9b8",
        ((), (", so ",), True),
        (
            (
                "_TASK_HAD37S",
                (
                    "pattern",
                    "(?P<who>\\b[A-Z][a-z]+(?: [A-Z][a-z]+)?) (?:has|has got|'s got|\\u2019s got) (?P<task>[a-z0-9' -]+? to [a-z]+(?: [a-z' -]+?)?)(?P<when> (?:before|by) [a-z' -]+?)?, so (?P<pro>she|he)(?:'ll| will)? (?:needs?|wants?|could use|could do with) (?P<x>[^,.;!?]+)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_telegraph34t": (
        "25c49474caea84b6",
        ((), (" order", ", ", "the "), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_that_is_a34r": (
        "0dca1559a8e7a81d",
        ((), ("everything that",), True),
        (
            (
                "_THAT_IS_A34R",
                (
                    "pattern",
                    "^everything that(?:'s| is) an? (?P<k>[a-z]+) (?:goes|go) (?P<p>on|onto|in|into) ",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_thats_hers36r": (
        "23772e433baf59ef",
        ((), ("that",), True),
        (
            (
                "_THATS_HERS36R",
                (
                    "pattern",
                    ",\\s*(?:and )?that(?:'s| is) (?P<pro>her|his) (?P<what>[a-z]+(?: [a-z]+)?(?: for the [a-z]+(?: [a-z]+)?)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_thats_n37r": (
        "95dc59dc80247504",
        ((), ("the ",), True),
        (
            (
                "_THATS_N37R",
                (
                    "pattern",
                    "^(?P<list>(?:both )?the [a-z ,]+?),\\s*that(?:'s| is| makes) (?P<n>two|three|four|both)(?: (?:things|items|of them))?,\\s*",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_the_one35r": (
        "3d6ef90d8b983e5b",
        ((), ("the one ", "there"), True),
        (
            (
                "_THE_ONE35R",
                (
                    "pattern",
                    "^there(?:'s| is) (?:just |only )?the one (?P<k>[a-z]+)(?: here)? and it(?:'s| is) (?:meant |intended )?for (?P<p>[^,.;!?]+?)(?P<rest>\\s*(?:[,.;!?].*)?)$",
                    34,
                ),
            ),
            (
                "_THE_SINGLE35R",
                (
                    "pattern",
                    "^there(?:'s| is) (?:just |only )?the (?:one|single|lone) (?P<k>[a-z]+)(?: here)?,\\s*so (?P<v>hand|give|pass|take|bring) (?:that|it)(?: one)? (?:over |across )?to (?P<p>[^,.;!?]+?)(?P<rest>\\s*(?:[,.;!?].*)?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_the_one_item37r": (
        "61f4cfacd01c40e4",
        ((), ("the one ",), True),
        (
            (
                "_THE_ONE_ITEM37R",
                ("pattern", "^(?:just |only )?the one (?:item|thing) for (?=[^:]+:)", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_them_listed33r": (
        "1e32f37e3aef4c20",
        ((), (" of them,",), True),
        (
            (
                "_THEM_LISTED33R",
                (
                    "pattern",
                    "\\bthe (?P<n>two|three|four|five|six) of them,\\s*(?P<x>[a-z][a-z ]*?(?:,\\s*[a-z][a-z ]*?)* and [a-z][a-z ]*?),",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_them_remark36r": (
        "512b3ed255a76df7",
        ((), ("the ",), True),
        (
            (
                "_THEM_REMARK36R",
                (
                    "pattern",
                    ",\\s*(?P<who>the [a-z]+) (?:keeps |kept |has been |'s been |is always |always |will only )?(?:knock(?:ing|ed|s)? (?:them|those) (?:over|off|down)|(?:nick(?:ing|ed|s)?|pinch(?:ing|ed|es)?|borrow(?:ing|ed|s)?|los(?:ing|t|es)|swip(?:ing|ed|es)|hid(?:ing|den|es)?|misplac(?:ing|ed|es)) (?:them|those))(?: again)?(?: and never (?:said|asked|told anyone|brought them back|gave them back))?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_then_header36t": (
        "0523b834e265ca52",
        ((), (" for ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_theres_one36r": (
        "8b1f5c3eaf1361f4",
        ((), (" and only ", "there"), True),
        (
            (
                "_ONLY_ONE_TO36R",
                (
                    "pattern",
                    "^there(?:'s| is) only (?:the )?one (?P<k>[a-z]+) and only (?P<p>[a-z][\\w ]*?) to (?:give|take|hand) it to,\\s*so (?:off it goes to|(?:give|take|hand) it to) (?P<pro>her|him)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
            (
                "_THERES_ONE36R",
                (
                    "pattern",
                    "^there(?:'s| is) (?:a|one|a single|just the one|only the one|only one|the one) (?P<k>[a-z]+)(?: (?:about|here|left|going|over there|on the go))?,\\s*(?:so\\s+)?(?P<v>take|give|bring|hand|pass) it (?P<rest>(?:to|over to) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_thing_cleft34t": (
        "4af6583019103a4e",
        ((), ("the thing ",), True),
        (("_sub", ("function", "hltl.grounding._normalise1:_sub", "eb004bf21c503e77")),),
    ),
    "hltl.grounding._normalise4:_thing_each33r": (
        "3d0135d978f659ee",
        (
            (),
            (
                "ach of them",
                "both of them",
                "both people",
                "item",
                "the two people",
                "them both",
                "thing",
                "verybody",
                "veryone",
            ),
            True,
        ),
        (
            (
                "_THING_EACH33R",
                (
                    "pattern",
                    "^(?:(?:a|one) (?:thing|item) (?:for each of them|(?:apiece|each) for (?:them|the two of them)|each|apiece)(?:,\\s*mind)?|(?:everyone|everybody|each of them) gets? (?:one|a) (?:thing|item)|give (?:the two people|both people|them both|both of them|each of them) (?:a single|one|a|an) (?:item|thing) each)\\s*[,:]\\s*(?P<list>[^;.!?]+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_though_stays35r": (
        "f2a8908ef1c7a0a8",
        ((), ("stays",), False),
        (),
    ),
    "hltl.grounding._normalise4:_to_eat37s": (
        "d2cd480cade7861f",
        ((), ("something ",), True),
        (
            (
                "_TO_EAT37S",
                (
                    "pattern",
                    "\\bsomething (?P<what>to eat|to nibble|to snack on|to drink)\\s*,?\\s*(?:but |just |only )?not (?P<x>the [a-z' -]+?)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_to_his_do37r": (
        "9a77d3a31cdc1ff2",
        ((), ("to ",), True),
        (
            (
                "_TO_HIS_DO37R",
                (
                    "pattern",
                    ",\\s*(?:off )?to (?P<pro>his|her) (?P<what>[a-z]+(?: [a-z]+)?) (?:do|party|bash|night|session|class|club|practice|rehearsal|recital|match|meeting)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_to_one_other33r": (
        "3ac4fd2777fa5260",
        ((), (" the other",), True),
        (
            (
                "_TO_ONE_OTHER33R",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?) and (?P<q>[A-Za-z][\\w ]*?) both (?:want|need|would like) (?:an? [a-z]+|something)\\s*,\\s*so (?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:to|for) one(?: of them)? and (?P<y>(?:the )?[a-z]+(?: [a-z]+)?) (?:to|for) the other(?: one)?(?:,\\s*(?:whichever|either|any) way(?: round)?)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_trailing_remark32s": (
        "608fd448b729e25d",
        (
            (
                "'d",
                "'ll",
                "'m",
                "'re",
                "'s",
                "'ve",
                "am",
                "are",
                "asked",
                "can",
                "comes",
                "could",
                "did",
                "does",
                "goes",
                "had",
                "has",
                "have",
                "is",
                "keeps",
                "kept",
                "looks",
                "must",
                "said",
                "says",
                "seems",
                "should",
                "sounds",
                "told",
                "was",
                "went",
                "were",
                "will",
                "would",
            ),
            (),
            True,
        ),
        (
            (
                "_BETWEEN32S",
                (
                    "pattern",
                    "(?P<cut>,\\s*(?P<said>(?P<who>(?i:he|she|they|(?:his|her|their) [a-z]+)|[A-Z][a-z]+(?: [A-Z][a-z]+)?)(?P<pred>(?:'s|'re|\\s+(?:is|are|was|were|has|have|had|will|would))\\b[^,.;!?]*))\\s*,)(?=\\s*(?:and\\s+|so\\s+|just\\s+)?(?i:give|hand|pass|bring|take|put|place|pop|send|move)\\b)",
                    32,
                ),
            ),
            (
                "_TRAILING32S",
                (
                    "pattern",
                    "(?P<cut>[,.;!?]\\s*(?:(?i:and|cos|because)\\s+)?(?P<said>(?P<who>(?i:he|she|they|i|we|(?:his|her|their|my|our) [a-z]+)|[A-Z][a-z]+(?: [A-Z][a-z]+)?)(?P<pred>(?:'s|'re|'m|'ve|'ll|'d|\\s+(?:is|are|am|was|were|has|have|had|will|would|says|said|asked|told|keeps|kept|does|did|can|could|should|must|looks|seems|sounds|goes|went|came|comes))\\b[^,.;!?]*)))(?P<end>[.!?]*)\\s*$",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_two_one_each33r": (
        "4668ae9d662ab9fa",
        ((), (" and ",), True),
        (
            (
                "_TWO_ONE_EACH33R",
                (
                    "pattern",
                    "^(?:the )?two (?P<kind>[a-z]+)s,\\s*one (?:to|for) (?P<p>[A-Za-z][\\w ]*?),? and (?:one|the other) (?:to|for) (?P<q>[A-Za-z][\\w ]*?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_understood35t": (
        "30b564ae39a25218",
        (
            (),
            (
                "capiche",
                "capisce",
                "comprende",
                "follow me",
                "get it",
                "got that",
                "savvy",
                "understood",
            ),
            True,
        ),
        (
            (
                "_UNDERSTOOD35T",
                (
                    "value",
                    "',?\\\\s*(?:capisce|capiche|comprende|comprendez|savvy|understood|got that|you got that|get it|follow me)\\\\s*\\\\?\\\\s*$'",
                ),
            ),
            ("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),
        ),
    ),
    "hltl.grounding._normalise4:_unknown_corrected37r": (
        "ed69bb236a7403d7",
        ((), ("the ",), True),
        (
            (
                "_UNKNOWN_CORRECTED37R",
                (
                    "pattern",
                    "^(?P<x>(?:the )?[a-z]+) (?P<to>for|to) (?P<p>[a-z][\\w ]*?),\\s*(?:(?:or |oh )?no|sorry|correction|my mistake|my bad|oh dear|oops|whoops|wait|hang on|hold on|hang about|actually|what am i saying)(?:,?\\s*(?:(?:or |oh )?no|sorry|correction|my mistake|my bad|oh dear|oops|whoops|wait|hang on|hold on|hang about|actually|what am i saying))*,?\\s*(?:i (?:meant|mean)(?: to say)?,?\\s*)?(?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_want_with36": (
        "4c2eb91021d5cb5a",
        ((" will ", "'ll "), (), False),
        (),
    ),
    "hltl.grounding._normalise4:_wants_to_use34r": (
        "911ea8e22c5e68a8",
        ((), ("needs", "wants", "would like"), True),
        (
            (
                "_WANTS_TO_USE34R",
                (
                    "pattern",
                    "\\b(?P<w>wants|needs|would like) to (?:read|use|borrow|eat|drink|wear|play with) (?=the |an? )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_wants_to_v36r": (
        "c63cff9420e33acb",
        ((), ("'d like", "'s going", "is going", "needs", "wants", "would like"), True),
        (
            (
                "_WANTS_TO_V36R",
                (
                    "pattern",
                    ",\\s*(?P<p>[a-z][\\w ]*?) (?:wants|needs|is going|'s going|would like|'d like) to (?:(?:stack|sort|count|line up|build with|play with|paint|colour|color|look at|tidy|check|label|dry|clean|wash) (?:them|those|it)(?: up| out)?|(?:plate|dish|serve) up(?P<what> the [a-z]+)?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_way_about37r": (
        "b4d7150b0318e76c",
        ((), ("the other way about",), True),
        (("_WAY_ABOUT37R", ("pattern", "\\bthe other way about\\b", 34)),),
    ),
    "hltl.grounding._normalise4:_we_have34r": (
        "f9cd43ac7303d243",
        ((), ("everything",), True),
        (
            (
                "_WE_HAVE34R",
                ("pattern", "\\b(?P<e>everything) (?:we've got|we have got|we have)\\b", 34),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_what_she_wants35s": (
        "8a0fcb10335b8dba",
        ((), ("what ",), True),
        (
            (
                "_WHAT_SHE_WANTS35S",
                (
                    "pattern",
                    "(?:^|(?<=[,;.!?]\\s))(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:is|are|'s|'re) (?:just |exactly )?what (?P<pron>she|he)\\s?(?:really )?(?:(?:wants|needs|is after|'s after|is hoping for|'s hoping for|is wanting|'s wanting|is craving|'s craving|craves|fancies|is longing for|'s longing for|would like|'d like|has asked for|asked for|is waiting for|'s waiting for)|'s needing|is needing)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_whats_name36r": ("13693d6152c5b600", ((), ("name",), False), ()),
    "hltl.grounding._normalise4:_when_talked35s": (
        "7620f453b0bf2028",
        ((), (" about ",), True),
        (
            (
                "_WHEN_TALKED35S",
                (
                    "pattern",
                    "(?P<want>\\b(?:was|were|'s been|has been|had been) (?:on|going on|banging on|asking) about (?:(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?|it|them)) (?P<when>(?:before|during|after|at) (?:the|her|his|their|this|that) (?:[a-z]+ ){0,2}[a-z]+)(?=\\s*[,;])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_where_live34r": (
        "6da186da1d4ca2b1",
        ((), (" where ",), True),
        (
            (
                "_WHERE_LIVE34R",
                (
                    "pattern",
                    "^the (?P<s>[a-z]+(?: [a-z]+)?)(?:'s| is) where (?P<x>the (?:two |three |four )?[a-z]+) (?:live|belong|go|are kept|get kept),?\\s*so (?P<p>in|on) (?:they|them) go(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_where_was_i36r": ("a8a9f4c1c8665029", ((), ("the,",), False), ()),
    "hltl.grounding._normalise4:_which_is_list33r": (
        "0120a1851abc6960",
        ((), ("which ",), True),
        (
            (
                "_WHICH_IS_LIST33R",
                (
                    "pattern",
                    "\\bthe (?P<desc>[a-z]+ (?:things|items|bits|stuff)),\\s*which (?:is|are|means) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:plus|and|with) (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)(?=\\s*(?:[,;.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_which_robot35r": (
        "084d9eefb0be9e75",
        (
            (),
            ("available", "closer", "closest", "free", "idle", "nearer", "nearest", "not busy"),
            True,
        ),
        (
            (
                "_WHICH_ROBOT35R",
                (
                    "pattern",
                    "^(?:whichever|any) (?:robot|arm|one of you|of you)(?:'s| is) (?:idle|free|available|not busy|nearest|closest|nearer|closer) (?:can|could|should|may|will) (?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_whichever_closer34r": (
        "9b32dd59ae79c2f9",
        ((), ("whichever ",), True),
        (
            (
                "_WHICHEVER_CLOSER34R",
                (
                    "pattern",
                    "^whichever (?:one's|ones|one is|is|'s) (?P<adj>closer|nearer|closest|nearest) to (?P<p>[a-z][\\w ]*?),\\s*give (?P<pro>her|him) (?:that|it)(?: one)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_whichever_of34r": (
        "69f13f9c2d235a4b",
        ((), ("whichever of ",), True),
        (
            (
                "_WHICHEVER_OF34R",
                (
                    "pattern",
                    "^whichever of (?P<p>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+) and (?P<q>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+) (?:is|'s) (?P<adj>closer|nearer|closest|nearest)(?P<to> to (?:you|the robot|your gripper|hand))? (?:gets|can have|should get|takes) (?P<x>.+?)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_whichever_of_them36r": (
        "93fdbe136de76b1f",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._normalise4:_whichever_person33r": (
        "db5ac29454be1584",
        ((), ("whichever of the",), True),
        (
            (
                "_WHICHEVER_PERSON33R",
                (
                    "pattern",
                    "^whichever of (?:the two(?: people)?|them) is (?:closer|nearer|nearest|closest|free|handier)(?: to you)? (?P<rest>(?:can have|gets|should get|can take) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_who_getting35r": (
        "1ce755337f6241e9",
        ((), ("getting",), False),
        (
            (
                "_WHO_GETTING35R",
                (
                    "pattern",
                    "(?P<cue>\\b(?:hang about|hang on|hold on|wait)),\\s*no,\\s*it(?:'s| is) (?P<p>[^,.;!?]+?) who(?:'s| is) getting (?P<it>it|them)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_who_which37r": (
        "cfdae30a34addaa1",
        ((), (" for ",), True),
        (
            (
                "_WHO_WHICH37R",
                (
                    "pattern",
                    "\\b(?P<head>(?:apiece|each) for [a-z][\\w ]*? and [a-z][\\w ]*?),\\s*(?:i|we) (?:don't|do not) (?:care|mind) (?:who (?:ends up with|gets|has) which|which (?:one )?(?:goes to|gets) who)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_whose_then36": (
        "fa6793c93006350e",
        (("dropped", "forgotten", "left", "lost", "mislaid", "misplaced"), ("so ",), True),
        (
            (
                "_ARE_WHOSE36",
                (
                    "pattern",
                    "^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:are|is|'s|belongs? to) (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s)?,\\s*so (?P<req>.+)$",
                    34,
                ),
            ),
            (
                "_LOST_HIS36",
                (
                    "pattern",
                    "^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| has) (?:lost|forgotten|mislaid|misplaced|dropped|left) (?P<pos>his|her|their) (?P<x>[a-z][a-z ]*?),\\s*(?:so\\s+)?(?P<req>.+)$",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_will_do_for35r": (
        "0b65cc5fc7f5d167",
        ((), (" will do ",), False),
        (),
    ),
    "hltl.grounding._normalise4:_will_do_him37r": (
        "eecc5c1b9dbaeee8",
        ((), (" will do ",), True),
        (
            (
                "_WILL_DO_HIM37R",
                (
                    "pattern",
                    "^(?P<p>[a-z][\\w ]*?)(?:'s| is) (?:only|just) [a-z]+ing\\b(?P<why>[^,]*),\\s*so (?P<x>any [a-z]+)(?: at all)? will do (?:for )?(?P<pro>him|her)(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_with_one_there35t": (
        "0dd08a67330e7112",
        ((), (" with ",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding._normalise4:_wont_mind_if37r": (
        "5549df5d21a84641",
        ((), (" mind ",), True),
        (
            (
                "_WONT_MIND_IF37R",
                (
                    "pattern",
                    "^(?P<head>(?P<p>[a-z][\\w ]*?) (?:can have|gets|is to have|should have|can take) (?:a|one) (?P<k>[a-z]+)),\\s*(?P<pro>she|he) (?:won't|will not|doesn't|does not) mind (?:if|whether) (?:it's|it is) (?P<a>the [a-z]+)(?: one)? or (?P<b>the [a-z]+)(?: one)?(?P<end>\\s*[.!]?)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise4:_wrong_way35r": (
        "52b3b46b244480c8",
        ((), ("wrong way",), False),
        (),
    ),
    "hltl.grounding._normalise4:_zero_copula34s": (
        "af67da85a613a6b5",
        ((), ("he",), True),
        (
            (
                "_ZERO_COPULA34S",
                (
                    "pattern",
                    "(?P<lead>(?:^|[,.;!?])\\s*)(?P<who>he|she|they)\\s+(?=(?:really |so |very |also |still )?(?:thirsty|hungry|parched|gasping|peckish|starving|famished|ravenous|cold|freezing|tired|knackered|shattered|exhausted|sore|sticky|soaked|boiling|sweaty)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise5:_about_them37": (
        "a3cfda5dedb03b6c",
        (
            (),
            (
                " at ",
                "after",
                "all afternoon",
                "all day",
                "all morning",
                "all night",
                "all week",
                "and that's ",
                "between shifts",
                "darling",
                "from",
                "lamb",
                "mite",
                "monkey",
                "off duty",
                "on a break",
                "on earlies",
                "on her day off",
                "on his day off",
                "on holiday",
                "on lates",
                "on leave",
                "on nights",
                "one",
                "pickle",
                "rascal",
                "scamp",
                "since dawn",
                "since first thing",
                "soul",
                "sweetheart",
                "thing",
            ),
            True,
        ),
        (
            (
                "_BACK_FROM37",
                (
                    "pattern",
                    "(?<=[.!?])\\s+(?P<pron>he|she)(?:'s| is) (?:just |only just |only )?(?:(?:back|home|in) from|(?:tired|worn out|exhausted|shattered|knackered|sleepy|hungry|thirsty|sore|wet|cold|starving|parched|done in) (?:from|after)) (?P<doing>[a-z]+(?: [a-z]+)?)\\s*[.!]?\\s*$",
                    34,
                ),
            ),
            (
                "_BOTH_BEEN37",
                (
                    "pattern",
                    ",\\s*they(?:'ve| have) (?:both|all) been (?P<what>[a-z]+(?: [a-z]+){0,3}?) (?:all day|all morning|all afternoon|all night|all week|since dawn|since first thing)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_HERS_AT37",
                (
                    "pattern",
                    "(?<=[.!?])\\s+(?P<pron>his|her) (?P<what>[a-z]+(?: [a-z]+)?) (?:starts|finishes|ends|kicks off|is over|begins) at (?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|[0-9]{1,2})(?: o'clock| oclock| ?[ap]m)?\\s*[.!]?\\s*$",
                    34,
                ),
            ),
            (
                "_SHE_IS_A37",
                (
                    "pattern",
                    ",\\s*(?P<pron>he|she)(?:'s| is) (?:a|such a|a right|a proper|a real|an) (?P<what>(?:[a-z]+ ){0,2}(?:thing|one|soul|mite|lamb|monkey|scamp|rascal|pickle|sweetheart|darling)|[a-z]+(?: [a-z]+)? (?:on leave|off duty|on holiday|on his day off|on her day off|on a break|between shifts|on nights|on earlies|on lates))(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_THATS_HER37",
                (
                    "pattern",
                    "(?:,\\s*|\\s+)and that's (?P<pron>her|him|them|everyone|everybody) (?:sorted|done|set|happy|settled|seen to)(?: out)?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise5:_courtesies37": (
        "394d34ee881935fb",
        (
            (),
            (
                "'s ",
                "could do with",
                "could use",
                "from ",
                "need",
                "then ",
                "too much to ask",
                "want",
            ),
            True,
        ),
        (
            (
                "_MEANT_FOR37",
                (
                    "pattern",
                    "\\b(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)'s (?=(?:meant|intended|supposed|reserved|earmarked|set aside) for\\b)",
                    34,
                ),
            ),
            (
                "_NEED_ROOM37",
                (
                    "pattern",
                    "(?P<lead>,\\s*|\\s+and\\s+)(?:I|we) (?:need|want|could use|could do with) (?:the |some |a bit of |a bit more |more )?(?P<what>room|space|elbow room|desk space|floor space)(?P<end>\\s*[.!?]?)\\s*$",
                    34,
                ),
            ),
            (
                "_SIGNED37",
                (
                    "pattern",
                    ",\\s*(?:and\\s+)?from (?:a|an|the|one|your|yours truly, a) (?:(?:very|rather|pretty|really|ever so|so|most) )?(?:(?P<adj>tired|weary|grateful|thankful|thirsty|hungry|busy|happy|exhausted|knackered|humble|harassed|frazzled|cold|wet|worn-out|worn out|old|young|friendly|hard-working|hardworking) )?(?P<trade>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_THEN_ALL37",
                (
                    "pattern",
                    "\\s+(?:and )?then (?P<c>(?:that's|that is) (?:all|it|everything))\\b",
                    34,
                ),
            ),
            (
                "_TOO_MUCH37",
                (
                    "pattern",
                    ",?\\s*if (?:it's|it is|that's|that is|it isn't|that isn't) (?:not )?too much to ask(?: of you| of anyone)?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise5:_so_to_last37": (
        "1c59effe5310a902",
        ((" is what ",), ("and ",), True),
        (
            (
                "_SO_TO_LAST37",
                (
                    "pattern",
                    "^(?P<first>.+?),\\s*and (?P<last>[^,.;!?]+?),\\s*so (?P<req>(?:pass|give|hand|take|bring) (?:it|them)(?: over)? to )(?P<pron>him|her)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_WHAT_ASKED37",
                (
                    "pattern",
                    "(?<=, and )(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) is what (?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?P<v>asked for|wanted|wants|needs|ordered|is after)\\b",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise5:_splits37": (
        "b2ce746c442dc7c7",
        (
            (),
            (
                " can ",
                " with ",
                " you ",
                "'you reckon",
                "'you think",
                "o you reckon",
                "o you think",
                "out of ",
            ),
            True,
        ),
        (
            (
                "_CAN_SIT37",
                (
                    "pattern",
                    "(?<=[.;!?])\\s+(?:and |also |oh, and )?(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) can (?:sit|go|live|stay) (?P<on>on|onto|in|into) (?P<s>the [a-z]+(?: [a-z]+)?)(?=\\s*(?:[.!]|$))",
                    34,
                ),
            ),
            (
                "_DO_FOR37",
                (
                    "pattern",
                    "^(?:could|can|would|will) you (?:please )?do (?P<rest>.+?)\\s*\\?\\s*$",
                    34,
                ),
            ),
            (
                "_DO_YOU_THINK37",
                (
                    "pattern",
                    ",\\s*(?:do you think|d'you think|do you reckon|d'you reckon)(?=\\s*\\?)",
                    34,
                ),
            ),
            (
                "_OUT_OF_REACH37",
                (
                    "pattern",
                    "\\s+out of (?P<p>[a-z]+(?: [a-z])?)(?:'s|s|') reach(?:,\\s*(?P<pron>he|she)(?:'s|s| has) had (?:plenty|enough|too many|too much|loads|his fill|her fill|his share|her share)(?: already)?)?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_WITH_IT37",
                (
                    "pattern",
                    "\\b(?P<to>(?:on|onto|in|into|up on|over to|to) (?P<s>the [a-z]+(?: [a-z]+)?|(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))) with (?P<pron>it|them)(?=\\s*(?:[.!;]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._normalise5:_wants_framed37": (
        "b95ec4d4803db13f",
        (
            (" the ",),
            (
                " could ",
                " have",
                " on at ",
                " say no to",
                " the one ",
                " would kill for",
                "after",
                "by the look",
                "following",
                "for ",
                "need of",
                "would ",
            ),
            True,
        ),
        (
            (
                "_BY_LOOK37",
                (
                    "pattern",
                    ",\\s*by the looks? of (?P<pron>him|her|them|things|it)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_FOR_DOING37",
                (
                    "pattern",
                    "\\s+for (?P<v>[a-z]{3,}ing) (?P<what>(?:the |those |these |some |a |an )?[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_HOUR_OF37",
                (
                    "pattern",
                    "^(?:after|following) (?:a|an|one|two|three|the) (?:(?:whole|full|long|hard|solid|entire|busy|good) )?(?:hour|hours|day|morning|afternoon|evening|week|session|shift|stint|night) (?:of|at) (?P<doing>[a-z]+(?: [a-z]+)?),\\s*",
                    34,
                ),
            ),
            (
                "_IN_NEED37",
                (
                    "pattern",
                    "\\b(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))(?:(?:'s| is) the one (?:who's|who is|that's|that is) in (?:dire |real |urgent )?need of|(?:'s| is) in (?:dire |real |urgent )?need of|(?:'s| has) (?:got to|gotta) have| (?:wouldn't|would not) say no to|(?:'s| has) been on at (?:me|us) (?:about|for)|(?:'s| is) on at (?:me|us) (?:about|for)| would kill for| could (?:really |just )?go for) (?=(?:the|that|this|those|these|her|his|their) )",
                    34,
                ),
            ),
            (
                "_THE_THING37",
                (
                    "pattern",
                    "\\b(?P<be>is|are) the (?:(?:one|only|very) )?things? (?:that |which )?(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))(?P<v>'s been|'s|has been|is|was|had been|'d been) (?P<w>craving|wanting|after|on about|asking for|dreaming of|longing for|hankering after|going on about)\\b",
                    32,
                ),
            ),
            (
                "_WOULD_QUITE37",
                (
                    "pattern",
                    "\\bwould (?:quite|really|rather|so|just|very much|dearly|truly) (?P<v>fancy|like|love)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_after_doing38": (
        "84db8dc775d8bc9b",
        ((), ("after", "following", "since"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites38:_courtesies38": (
        "45a532745f9bddd3",
        (
            (),
            (
                "asked for",
                "expects",
                "likes",
                "needs",
                "on behalf of ",
                "prefers",
                "so if you ",
                "wants",
            ),
            True,
        ),
        (
            (
                "_ON_BEHALF38",
                (
                    "pattern",
                    "^on behalf of (?:our|the|my|all of us at the|everyone at the|us at the) (?P<who>[a-z]+(?: [a-z]+){0,3}),\\s*",
                    34,
                ),
            ),
            (
                "_SO_IF38",
                (
                    "pattern",
                    ",\\s*so if you (?:could|would|can|don't mind|wouldn't mind|would be so kind)(?=\\s*(?:,|[.!]?\\s*$))",
                    34,
                ),
            ),
            (
                "_WANTS_TIDY38",
                (
                    "pattern",
                    ",\\s*(?:the|our|my) (?P<who>[a-z]+(?: [a-z]+)?) (?:wants|likes|needs|prefers|expects|has asked for|asked for) (?:a|an) (?:tidy|clear|clean|empty|neat|spotless|uncluttered|free) (?P<what>[a-z]+)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_fronted38": (
        "39d97f53d60e5495",
        (
            (),
            (" from", "cleanse", "detox", "diet", "fast", "health kick", "off to", "training for"),
            True,
        ),
        (
            (
                "_FRONTED38",
                (
                    "pattern",
                    "^(?P<p>(?:(?:mr|mrs|ms|miss|dr|person) )?[a-z]+?)(?:'s|s| is) (?:just )?(?P<state>(?:back|home|in|fresh) from|on (?:a|her|his) (?:diet|health kick|detox|fast|cleanse)(?: for)?|in training for|training for|off to) (?P<what>(?:the|his|her|their|a|an) [a-z' -]+?),?\\s+so (?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_lower38": (
        "f17fbfba8d7b4e8a",
        ((), ("always", "ever", "for ", "normal", "usual"), True),
        (
            (
                "_FOR_TRADES38",
                (
                    "pattern",
                    "\\s+for (?:the|our|my|his|her) (?P<who>[a-z]+(?: [a-z]+)?)(?:'s|s'|s) (?P<what>[a-z]+(?: [a-z]+){0,2})(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_HABIT38",
                (
                    "pattern",
                    "\\s*,?\\s+(?:like|as|same as) (?:every time|always|ever|usual|per usual|normal)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_pronouns38": (
        "79e43cb5ea533879",
        ((" with ", "asking", "enquiring", "inquiring"), ("i mean", "the one with "), True),
        (
            (
                "_ASKING_AFTER38",
                (
                    "pattern",
                    "\\b(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?:was|is|'s|has been|'s been|had been) (?:asking|enquiring|inquiring) (?:after|about) (?=(?:the|his|her|their|that|this) )",
                    32,
                ),
            ),
            (
                "_DONE_WITH38",
                (
                    "pattern",
                    "^(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))(?:'s| is| has) (?:done|finished) with (?P<x>(?:the|his|her|that|this) [a-z]+(?: [a-z]+)?),\\s*(?:(?P<pron>he|she)(?:'s| is) (?P<why>[a-z' ]+?),\\s*)?so (?:it|that) (?:can|could|should|may) (?:go|live) (?P<where>(?:back )?(?:in|on|into|onto) .+)$",
                    32,
                ),
            ),
            (
                "_IT_I_MEAN38",
                (
                    "pattern",
                    "^(?P<pre>[^,]*?)\\bit\\b(?P<mid>[^,]*),\\s*(?P<x>(?:the|that|this|her|his|their) [a-z]+(?: [a-z]+)?),\\s*I mean\\b(?P<sep>,\\s*|\\s*[.!]?\\s*$)",
                    34,
                ),
            ),
            (
                "_ONE_WITH38",
                (
                    "pattern",
                    ",\\s*the one with (?P<d>(?:a|an|the|some) [a-z' -]+?) on (?:the|its) (?:cover|front|back|label|lid|side|spine|top)(?=\\s*(?:[;,.!]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_questions38": (
        "fd9ee2b3c5ad92b6",
        ((" about ", "ready for "), (" from ", "my", "our", "the"), True),
        (
            (
                "_BACK_FROM38",
                (
                    "pattern",
                    "(?<=[.!?])\\s+(?P<pron>he|she)(?:'s| is) (?:just |only just )?(?:back|home|in) from (?P<whose>his|her) (?P<doing>[a-z-]+(?: [a-z-]+){0,2})\\s*[.!]?\\s*$",
                    34,
                ),
            ),
            (
                "_HOW_ABOUT38",
                (
                    "pattern",
                    "^(?:how|How) about (?P<req>(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?:gets|has|takes|can have) .+?)(?:,\\s*(?:seeing as|since|as|because) (?:he|she|they) (?:asked|got here|came|was here|were here) first)?\\s*\\?\\s*$",
                    32,
                ),
            ),
            (
                "_READY_FOR38",
                (
                    "pattern",
                    ",\\s*(?:all )?ready for (?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))(?:'s|s) (?:tea|lunch|dinner|breakfast|supper|snack|bath|nap|bedtime|feed|bottle time)(?: (?:after|before) (?:the|his|her) (?P<ev>[a-z-]+(?: [a-z-]+)?))?(?P<end>\\s*[.!?]?)\\s*$",
                    32,
                ),
            ),
            (
                "_THIRD_PARTY38",
                (
                    "pattern",
                    "(?<=[.!?])\\s+(?:the|our|my) (?P<words>[a-z][a-z' ]*?)\\s*[.!]?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_remarks38": (
        "91b62b165aa6455a",
        (
            (),
            (
                " got ",
                " out",
                "achy",
                "exhausted",
                "famished",
                "hungry",
                "offered",
                "owes",
                "parched",
                "peckish",
                "promised",
                "shattered",
                "sleepy",
                "sore",
                "starving",
                "stiff",
                "sweaty",
                "thirsty",
                "tired",
            ),
            True,
        ),
        (
            (
                "_GOT_HER38",
                (
                    "pattern",
                    ",\\s*(?P<pron>he|she)(?:'s| has) got (?P<whose>his|her) (?P<what>[a-z-]+(?: [a-z-]+){0,2}) (?:practice|lesson|class|rehearsal|session|shift|match|game|training|appointment|meeting|exam|audition)(?: (?:and|so) (?:wants|needs|would like|fancies|could do with) (?:a|an|some) (?:brew|cuppa|drink|snack|bite|sit down|sit-down|rest|breather|sugar boost)(?: first| beforehand| before that| before it)?)?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_LEFT_THEM38",
                (
                    "pattern",
                    "(?:[,;]\\s*|(?<=[.!])\\s+)(?P<whose>his|her|their|the|all that|that) (?P<what>[a-z-]+(?: [a-z-]+){0,2}) (?:(?:makes|made|leaves|left|gets|got|has made|has left) (?P<p1>him|her|them) (?:so |really |very |a bit |proper )?(?:thirsty|hungry|peckish|parched|starving|famished|tired|sleepy|sore|sweaty|achy|stiff|worn out|exhausted|shattered)|(?:tired|wore|wears|tires|has tired|has worn|wiped|has wiped|knocked|has knocked) (?P<p2>him|her|them) out)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_PROMISED38",
                (
                    "pattern",
                    ",\\s*(?:the|our|my) (?P<who>[a-z]+(?: [a-z]+)?) (?:promised|owes|offered|has promised|had promised) (?P<pron>him|her|them) (?:some|one|a few|a couple)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_splits38": (
        "2796950b3dfe84f3",
        ((), ("done", "finished", "free", "with "), True),
        (
            (
                "_DONE_FOR38",
                (
                    "pattern",
                    ",\\s*(?:and )?(?:then )?(?:you're|you are|youre) (?:done|finished|free|free to go)(?: for (?:the day|today|now|the night|the week|the shift))?(?=\\s*(?:,|[.!]?\\s*$))",
                    34,
                ),
            ),
            (
                "_WITH_AFTER38",
                (
                    "pattern",
                    ",\\s*with (?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?) (?P<on>on|in|onto|into) (?P<s>the [a-z]+(?: [a-z]+)?) (?:after that|afterwards|after|last|to finish|at the end)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38:_wants38": (
        "90662a91493aa321",
        ((), ("being a",), True),
        (
            (
                "_BEING_A38",
                (
                    "pattern",
                    ",\\s*being (?:a|an) (?P<what>[a-z]+(?: [a-z]+){0,5}),\\s*(?=(?:is|are|was)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38r:_all_the_word38r": ("9b15fa6a93f5045d", ((), ("all",), False), ()),
    "hltl.grounding._rewrites38r:_any_more38r": (
        "cee79803b85710f7",
        ((), ("just", "only"), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_any_old38r": (
        "56fb18640bf23189",
        ((), (" will do h", "any old"), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_both_listed38r": ("2622f54962bef9bb", ((), ("both",), False), ()),
    "hltl.grounding._rewrites38r:_each_pronouns38r": (
        "65c2225e586a89a6",
        ((), (" both ", " each "), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_either_named38r": (
        "dcd23b79330431c2",
        ((), ("either",), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_hates_others38r": (
        "47bf5173eb777b0d",
        ((), ("others",), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_leave_out38r": ("1409147ccaaa9810", ((), ("leave",), False), ()),
    "hltl.grounding._rewrites38r:_needs_something38r": (
        "286c5c2713ed9fea",
        ((), ("will do",), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_never_mind38r": ("6427042a5c6327e9", ((), ("never",), False), ()),
    "hltl.grounding._rewrites38r:_no_matter38r": (
        "ab798f09ed08d0f5",
        ((), ("matter", "regardless"), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_not_whose38r": ("2bd78b1645a2afb2", ((), ("not",), False), ()),
    "hltl.grounding._rewrites38r:_on_shift38r": (
        "fea3ede6f95a7a45",
        (("round",), (" break", " shift"), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_one_of_role38r": (
        "a1163948f3faf55c",
        ((), ("one of the",), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_only_the_one38r": ("5ec20b1a544a3f9d", ((), ("one",), False), ()),
    "hltl.grounding._rewrites38r:_or_one_of38r": ("891e7f03ea587200", ((), (" or ",), False), ()),
    "hltl.grounding._rewrites38r:_shouldnt_get38r": (
        "ddefd6c4725499fb",
        ((" not ", "n't"), (), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_so_not38r": ("1b51d41a1eb9d0b1", ((), ("not",), False), ()),
    "hltl.grounding._rewrites38r:_so_stops38r": ("fa8fe3bdd6fed701", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites38r:_something_listed38r": (
        "da4f108ed26a3a61",
        ((",", ":"), (), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_them_named38r": ("d5401ea0ce2f390b", ((), ("them",), False), ()),
    "hltl.grounding._rewrites38r:_too_thin38r": (
        "8d99ab83e3cb48ef",
        ((), ("not that one",), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_wants_to_so38r": ("5ca3f05fb192774d", ((), ("so",), False), ()),
    "hltl.grounding._rewrites38r:_whichever_first38r": (
        "cb460aefc2176469",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites38r:_who_asked38r": ("70730d3594c38b58", ((), (" who",), False), ()),
    "hltl.grounding._rewrites38r:_you_have38r": (
        "837b56d6d81441a1",
        ((), ("there", "you"), False),
        (),
    ),
    "hltl.grounding._rewrites38s:_corrections38s": (
        "284465feb079f7cb",
        (
            (),
            (
                " called",
                " out of ",
                " the one ",
                "actually",
                "after",
                "asked for",
                "asking for",
                "brain",
                "hang on",
                "he",
                "head",
                "hold on",
                "i am",
                "i'm",
                "memory",
                "mind",
                "needs",
                "not ",
                "that",
                "the ",
                "wait",
                "wanting",
                "wants",
                "who",
            ),
            True,
        ),
        (
            (
                "_CLEFT_WANT38S",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|oh,? correction|i mean|my mistake)\\s*,\\s*)it(?:'s| is) (?P<x>the [a-z][a-z ]*?) (?:(?P<p>he|she)(?:'s| is) (?:after|wanting|asking for)|(?P<q>he|she) (?:wants|needs|asked for))(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_FINE38S",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|oh,? correction|i mean|my mistake)\\s*,\\s*)(?P<pron>he|she)(?:'s| is) (?:fine|ok|okay|sorted|all right|alright|good|set)\\s*,\\s*(?=it(?:'s| is) )",
                    34,
                ),
            ),
            (
                "_IT_WHO38S",
                (
                    "pattern",
                    "(?P<head>\\b(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|oh,? correction|i mean|my mistake)\\s*,\\s*(?:[^,.;!?]+,\\s*)?)it(?:'s| is) (?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?:who|that)(?:'s| is| has) (?P<what>[^,.;!?]+?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_NAME_SEARCH38S",
                (
                    "pattern",
                    "\\b(?P<to>to|for),\\s*(?:(?:oh|er|erm|um|uh|ah)\\s*,?\\s*)?what(?:'s| is) (?P<pron>he|she) called(?: again)?\\s*[,?]\\s*(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))(?:\\s*,\\s*(?:that's it|that's the one|that's right|yes|yeah)(?:\\s*,\\s*(?P<again>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)))?)?(?=\\s*(?:[.!]|$))",
                    34,
                ),
            ),
            (
                "_NOT_TAKEN38S",
                (
                    "pattern",
                    "(?P<cue>(?<!\\bno )\\b(?:wait|hang on|hold on|hang about|actually)\\s*,\\s*)not (?P<x>the [a-z][a-z ]*?)\\s*,\\s*",
                    34,
                ),
            ),
            (
                "_OR_CUE38S",
                ("pattern", ",\\s*or,?\\s+(?P<cue>actually|wait|hang on|hold on)\\s*,", 34),
            ),
            (
                "_OUT_OF38S",
                (
                    "pattern",
                    "(?P<old>(?:the |some |a |an )?(?P<x>[a-z]+))(?P<mid>\\s*,\\s*(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|oh,? correction|i mean|my mistake)\\s*,\\s*)(?P<new>(?:the|some|a|an) [a-z][a-z ]*?)\\s*,\\s*(?:we're|we are|we've|we have|they're|you're|i'm)(?: all| clean| right)?(?: run)? out of (?:the |any )?(?P<y>[a-z]+)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_SAID_SO38S",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|oh,? correction|i mean|my mistake)\\s*,\\s*)(?P<who>he|she|(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?:said|says|reckons|told me)\\s+(?P<x>(?:(?:on|in|onto|into) )?the [a-z][a-z ]*?)(?=\\s*(?:[,.!]|$))",
                    34,
                ),
            ),
            (
                "_SLIP38S",
                (
                    "pattern",
                    ",\\s*(?P<er>er|erm|um|uh|oh|sorry)\\s*,\\s*(?:my (?:brain|head|mind|memory)(?:'s| is)|i'm|i am) (?P<what>[^,.;!?]+?)\\s*,\\s*(?=(?:i mean|i meant|sorry|no)\\b)",
                    34,
                ),
            ),
            (
                "_THE_ONE38S",
                (
                    "pattern",
                    "(?P<head>\\b(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|oh,? correction|i mean|my mistake)\\b[^.;!?]*?),\\s*(?:(?P<pron>he|she)|(?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)))(?:'s| is) the one (?P<what>(?:(?:who|that)(?:'s| is| has) )?(?:just )?(?:(?:back|in|home) from|been|[a-z]+ing)\\b[^,.;!?]*?)(?:,\\s*so (?P<so>him|her))?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites38s:_for_theirs38s": (
        "8cb0bab433cf5c03",
        ((), ("for ",), True),
        (
            (
                "_FOR_THEIRS38S",
                (
                    "pattern",
                    "(?<=[a-z])\\s+for (?P<pos>his|her) (?P<what>[a-z][a-z' -]*?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39:_after_all39": ("41c72216c84c841f", ((), (" after ",), False), ()),
    "hltl.grounding._rewrites39:_after_kind39": (
        "b5299628f8e7fae6",
        ((), ("after", "on the lookout for", "wanting"), True),
        (
            (
                "_AFTER_KIND39",
                (
                    "pattern",
                    "(?:\\s+is|'s) (?:after|wanting|on the lookout for) (?:a|an|some) (?:(?P<drink>drink|brew|cuppa|cup of tea|coffee|cold drink|drop of something)|(?P<food>snack|bite|nibble|bite to eat|sandwich|sarnie|butty))\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39:_at_all39": ("70c375a5f6c47e23", ((), (" at all ",), False), ()),
    "hltl.grounding._rewrites39:_courtesy39": (
        "f3b5db42de1b91d5",
        (
            (),
            (
                "chuck",
                "darling",
                "dear",
                "duck",
                "flower",
                "hen",
                "lad",
                "lass",
                "love",
                "mate",
                "pal",
                "pet",
                "sunshine",
                "sweetheart",
            ),
            True,
        ),
        (
            (
                "_THANKS_ADDRESS39",
                (
                    "pattern",
                    "^(?:ta|thanks|thank you|cheers)\\s*,?\\s+(?:pet|petal|love|hen|duck|chuck|flower|pal|mate|lad|lass|bonny lad|bonny lass|sunshine|dear|darling|sweetheart|me duck|my love)\\s*,\\s*(?:and\\s+)?(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39:_is_to39": ("558fc4080d9b66be", ((), ("'s to ",), False), ()),
    "hltl.grounding._rewrites39:_it_remark39": ("0d7e8a46389843f5", ((), (" it",), False), ()),
    "hltl.grounding._rewrites39:_only_one39": ("ae74465d20de8fe1", ((), ("only",), False), ()),
    "hltl.grounding._rewrites39:_order39": (
        "4fca9b76038d26d5",
        ((), ("after", "begin", "once ", "start", "waiting for", "waiting on", "wanting"), True),
        (
            (
                "_ONCE_SORTED39",
                (
                    "pattern",
                    "\\bonce (?:(?P<both>(?:both|both of them|they)(?: are|'re| have been)?|theyre)|(?P<pron>he|she)(?:'s|s| is| has been)) (?:sorted|sorted out|seen to|served|looked after|done|taken care of|dealt with)\\b",
                    34,
                ),
            ),
            (
                "_SORT_OUT39",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w ]*?)(?:'s| is) (?:after|wanting|waiting for|waiting on) (?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?),\\s*so (?:sort (?P<p1>him|her) out|see to (?P<p2>him|her))(?P<first> first)?(?=\\s*(?:[.;!]|$))",
                    34,
                ),
            ),
            ("_START_OFF39", ("pattern", "^(?:start|begin) (?:off|out) (?=with\\b)", 34)),
        ),
    ),
    "hltl.grounding._rewrites39:_pronouns39": (
        "0156496a18ca3a14",
        (("?", "if you ", "please"), ("as for ", "as regards ", "as to "), True),
        (
            (
                "_WHOSE_PLEASE39",
                (
                    "pattern",
                    "^(?P<x>(?:[Tt]he|[Tt]hat|[Tt]his) [a-z]+(?: [a-z]+)?)(?:'s| is) (?P<p>[A-Z][\\w ]*?)'s,\\s*(?P<c>if you (?:would|could|will|please|don't mind|wouldn't mind)|please)\\b",
                    32,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39:_questions39": (
        "ca3d40ec3d4aa2f2",
        (("?",), (" after ",), True),
        (
            (
                "_WAITED_AFTER39",
                (
                    "pattern",
                    "^(?P<s>(?P<p>[A-Z][\\w ]*?)(?:'s| has| is)(?: been)? (?:stood|standing|waiting|sat|sitting|queuing|queueing|hanging about|hanging around)(?: there| here| about| around)?(?: for (?:ages|a while|hours|an age|a good while|a bit))?) after (?P<pron>his|her|their) (?P<what>[a-z-]+(?: [a-z-]+){0,3})(?=[.!]\\s+\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39:_since_came39": ("a126cd703792b9dc", ((), ("since",), False), ()),
    "hltl.grounding._rewrites39:_want_idioms39": (
        "91da78d3df4c105b",
        ((), (" down for", " heart", "could "), True),
        (
            (
                "_WANT_IDIOM39",
                (
                    "pattern",
                    "(?:\\s+could (?:really |happily |easily |just |so )?(?:murder|kill for)|(?:\\s+has|'s)(?: got)? (?:his|her|their) hearts? (?:set|fixed) on|(?:\\s+has|'s)? put (?:his|her|their) names? down for)(?= (?P<det>a|an|some|the|that|this|those|these) (?P<x>[a-z]+(?: [a-z]+)?)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39r:_all_asked39r": ("e3cf9e03fa927d19", ((), ("all",), False), ()),
    "hltl.grounding._rewrites39r:_all_to39r": ("e723c0b0a7d0e248", ((), (", all ",), False), ()),
    "hltl.grounding._rewrites39r:_any_but39r": ("09fa0efadec725dd", ((), ("any ",), False), ()),
    "hltl.grounding._rewrites39r:_each_header39r": (
        "98061098a5145d77",
        (
            (),
            ("both of them", "one ", "the pair of them", "the two of them", "they", "you two"),
            True,
        ),
        (
            (
                "_EACH_HEADER39R",
                (
                    "pattern",
                    "^(?:(?:they|the two of them|the pair of them|both of them|you two) (?:each |both )?(?:get|gets|have|can have|are having) (?:one each|one apiece|(?:a|an|one) (?P<noun>[a-z]+)(?: each)?)|one (?:each|apiece)(?: for (?:the (?:pair|two) of them|both of them|them both|the pair|the two))?)(?P<adj>(?: (?:before|after|for|at|from) [^:,;]+?)?)\\s*:\\s*(?P<list>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39r:_hang_on39r": (
        "e9a1d05a64115a6d",
        ((), ("do not", "don't", "no need to"), True),
        (
            (
                "_HANG_ON39R",
                (
                    "pattern",
                    "^(?:(?:no|so) )?(?:don't|do not|no need to) (?:hang on to|hang onto|hold on to|hold onto|keep|hang on to|sit on) (?P<what>the [a-z]+(?: [a-z]+)?)\\s*[,;]\\s*(?:just )?(?P<req>(?:give|hand|pass|bring|take|put|place|pop|stick|set) .+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39r:_just_the_one39r": (
        "f9eb8522caecca22",
        ((), (" the one",), True),
        (
            (
                "_JUST_THE_ONE39R",
                (
                    "pattern",
                    "^(?P<head>(?:one|a|an|a single) [a-z]+(?: [a-z]+)?)\\s*,\\s*(?:just|only) the one\\s*(?:,\\s*|(?=[.!]?$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39r:_left_be39r": (
        "f039a0d9eb2b77c6",
        ((), ("leave", "move", "touch"), False),
        (),
    ),
    "hltl.grounding._rewrites39r:_make_do39r": (
        "c50f77208aac6d11",
        ((), (" with ", "make do"), False),
        (),
    ),
    "hltl.grounding._rewrites39r:_not_wanted39r": (
        "93a64d0c1b9c7e2c",
        ((), (" no ", "n't ", "not "), False),
        (),
    ),
    "hltl.grounding._rewrites39r:_owner39r": ("83c9707df829016e", (("'s",), (" is",), False), ()),
    "hltl.grounding._rewrites39r:_something_but39r": (
        "961cd1c688a62b99",
        ((), ("thing",), False),
        (),
    ),
    "hltl.grounding._rewrites39r:_stand39r": (
        "b7a306d54a132bdb",
        ((), ("stand ",), True),
        (
            (
                "_STAND39R",
                (
                    "pattern",
                    "^(?P<pre>(?:please |just |now )?)stand (?P<x>[^,;.!?]+?)(?: up(?:right)?)? (?P<on>on|onto|in|into) (?P<s>the [a-z]+(?: [a-z]+)?)(?=\\s*(?:[,;.!?]|$)| so\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39r:_that_is_to39r": ("ffa373f23e9777f0", ((), ("that",), False), ()),
    "hltl.grounding._rewrites39r:_whichever_again39r": (
        "f52353261aab787b",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites39r:_whichever_of39r": (
        "a508b6f481a27924",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites39r:_whichever_who39r": (
        "585ddbccea54aedf",
        ((), ("whichever ",), True),
        (
            (
                "_WHICHEVER_WHO39R",
                (
                    "pattern",
                    "^whichever (?P<role>[a-z]+(?: [a-z]+)?)(?:'s| is) (?:nearer|closer|nearest|closest|free|handier|quicker|about|around|nearby|free first)(?: to (?:you|hand))? (?P<v>can have|gets|should get|can take|should have|wants)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites39s:_corrections39s": (
        "e6e281d99f7b0e45",
        (
            (),
            (
                " go",
                " got th",
                " the one ",
                " what ",
                "daft me",
                "hold up",
                "i keep ",
                "ixed",
                "my ",
                "silly me",
                "silly old me",
                "that",
                "to ",
                "uddled",
                "who",
            ),
            True,
        ),
        (
            (
                "_GOES_TO39S",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|nope|sorry|no sorry|oh no|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|i mean|my mistake|oops|whoops)\\s*,\\s*)(?:it|they|that|that one)(?: should| ought to| needs to| has to| have to| must| can)? go(?:es)? (?=to\\s)",
                    34,
                ),
            ),
            (
                "_HOLD_UP39S",
                ("pattern", "(?P<lead>,\\s*(?:(?:ah|oh)\\s*,?\\s*)?)hold up(?=\\s*,)", 34),
            ),
            (
                "_ONE_NEEDING39S",
                (
                    "pattern",
                    "(?P<p>\\b(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+))(?:'s| is) the one (?:needing|wanting|after|asking for) (?P<it>it|them)(?: for (?:the|her|his|their) [a-z]+(?: [a-z]+){0,2})?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_PLACE_NOT39S",
                (
                    "pattern",
                    "^(?P<head>[^,;.!?]+?\\bto [^,;.!?]+?),\\s*(?:or\\s+)?(?P<cue>no|actually|sorry|no wait|rather)\\s*,\\s*(?P<where>(?:on|onto|in|into) (?:the )?[a-z][a-z ]*?)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_SLIP39S",
                (
                    "pattern",
                    "(?P<lead>,\\s*)(?P<cue>(?:(?:oh|ah|well)\\s*,?\\s*)?(?:(?:no|nope|sorry|no sorry|oh no|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|i mean|my mistake|oops|whoops))\\s*,\\s*)?(?:oh\\s*,?\\s*)?(?P<slip>i keep (?:saying|calling (?:him|her|them)|getting (?:them|those) (?:mixed up|muddled(?: up)?))(?P<said>(?: [a-z]+){0,2})|i(?:'ve| have) (?:muddled|mixed) (?:them|those|it|that)(?: up)?|i(?:'ve| have) got (?:them|those) (?:mixed up|muddled(?: up)?)|my (?:muddle|mix-up|mix up|bad)|silly me|daft me|silly old me)\\s*,\\s*",
                    34,
                ),
            ),
            (
                "_WHAT_ASKED39S",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|nope|sorry|no sorry|oh no|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|i mean|my mistake|oops|whoops)\\s*,\\s*)(?P<x>the [a-z][a-z ]*?)(?:'s| is) what (?P<who>he|she|(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?:asked for|wants|wanted|needs|needed|ordered|is after|'s after|was after)(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_WHO_IS_ABOUT39S",
                (
                    "pattern",
                    "(?P<cue>\\b(?:no|nope|sorry|no sorry|oh no|actually|wait|no wait|hang on|hold on|hang about|scratch that|correction|i mean|my mistake|oops|whoops)\\s*,\\s*)(?:(?P<gone>he|she)(?:'s| is) not (?:here|about|around|in)(?: today)?\\s*,\\s*)?it(?:'s| is) (?P<p>(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)) (?:who|that)(?:'s| is) (?:about|here|around|in)(?:\\s*,\\s*so (?:give|hand|pass|take) (?:it|them) (?:to )?(?P<pron>her|him))?(?P<end>\\s*[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites40:_any_going40": ("41896f069a10154a", ((), (" if ",), False), ()),
    "hltl.grounding._rewrites40:_bless40": ("c66a2dfe71998bed", ((), ("bless",), False), ()),
    "hltl.grounding._rewrites40:_finish_with40": ("d70ecda554046db7", ((), (" with ",), False), ()),
    "hltl.grounding._rewrites40:_left_on40": ("30b0fceaf6672fc7", ((), ("left",), False), ()),
    "hltl.grounding._rewrites40:_same40": ("577c7938483ae355", ((), ("ditto", "same"), False), ()),
    "hltl.grounding._rewrites40r:_asked_for40r": (
        "a1c016dbb70145df",
        ((), ("asked for",), False),
        (),
    ),
    "hltl.grounding._rewrites40r:_blame40r": (
        "97109e283d5fdb85",
        (
            (),
            (
                " my mistake",
                " not ",
                " that wrong",
                "confused",
                "correction",
                "correction from ",
                "er",
                "i got ",
                "i misspoke",
                "i'm all over the place",
                "mixed up",
                "muddled",
                "my bad",
                "my fault",
                "my mistake",
                "silly me",
                "uh",
                "um",
                "wrong name",
                "wrong one",
                "wrong person",
                "wrong way round",
            ),
            True,
        ),
        (
            (
                "_BLAME40R",
                (
                    "value",
                    "\"(?P<m>(?<=,\\\\s)(?:no|sorry|wait|no wait|hang on|hold on|oops|scratch that)\\\\s*,\\\\s*)(?:(?:um|erm|er|uh|oh)\\\\s*,\\\\s*)?(?:wrong name|wrong person|wrong one|my mistake|my bad|my fault|silly me|correction|i'm all over the place(?: today)?|i'm (?:getting )?(?:muddled|mixed up|confused)(?: today)?|i got (?:that|it) wrong|i misspoke)\\\\s*,\\\\s*(?=[a-z])\"",
                ),
            ),
            (
                "_CORRECTION_CUE33R",
                (
                    "pattern",
                    "[,.]\\s*(?:(?:oh|ah|er|um),? )?(?:hang (?:about|on),? i (?:got|had) that wrong|(?:hmm|hm|erm|um),? no,? my mistake|(?:a )?correction from (?:the )?[a-z]+(?: [a-z]+)?|no,? (?P<way>wrong way round|the wrong way round)|(?:no|well|ah|er|um|sorry),? not (?P<x>(?:the )?[A-Za-z]+(?: [A-Za-z]+)?))\\s*,\\s*(?P<fix>.+)$",
                    34,
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_claim40r": (
        "f48f5f9c16a20373",
        ((), ("bagged", "claim", "dibs", "name on"), False),
        (),
    ),
    "hltl.grounding._rewrites40r:_contrast40r": ("e20ba07bc0572914", ((" for ",), (), False), ()),
    "hltl.grounding._rewrites40r:_count_for40r": (
        "4361d85dd4de18c0",
        ((), (" for ",), True),
        (
            (
                "_COUNT_FOR40R",
                (
                    "value",
                    "'^(?P<n>two|three|four) (?:things|items|bits|jobs|deliveries) for (?P<k>two|three|four) (?:people|of them|folk)\\\\s*:\\\\s*(?=[a-z])'",
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_dont_but40r": (
        "d16b15398cdf0d18",
        ((), ("the ",), True),
        (
            (
                "_DONT_BUT40R",
                (
                    "value",
                    '"^(?:please )?(?:don\'t|do not) (?:put|place|set|stick|pop|lay) (?P<a>the [a-z]+(?: [a-z]+)?) (?P<prep>on|onto|in|into|on top of) (?P<s>the [a-z]+(?: [a-z]+)?)\\\\s*[,;]\\\\s*(?:(?:just|instead) )?(?P<v>put|place|set|stick|pop|lay) (?P<b>the [a-z]+(?: [a-z]+)?) (?:on|onto|in|into|on top of) (?:it|there|that)(?: instead)?(?P<end>\\\\s*[.!]?)$"',
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_gone_off40r": (
        "382f3227c81f79f6",
        ((), (" no ", " of ", " off ", " on "), False),
        (),
    ),
    "hltl.grounding._rewrites40r:_indifferent40r": (
        "09286e0f86b1150e",
        (
            (),
            ("bother", "choos", "either", "fuss", "matter", "one of the", "partic", "pick"),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites40r:_leave_first40r": (
        "b65aa4487e9aaa13",
        ((), ("the ",), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_LEAVE_FIRST40R",
                (
                    "value",
                    "'^(?:leave|forget about|skip) (?P<x>the [a-z]+(?: [a-z]+)?)\\\\s*,\\\\s*(?=(?:just|only) )'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_needs_list40r": (
        "9eb668f2701e5cc5",
        ((), ("'s after", "is after", "needs", "wants"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_NEEDS_LIST40R",
                (
                    "value",
                    "\"^(?P<p>[A-Za-z][\\\\w ]*?) (?P<v>needs|wants|is after|'s after) (?:some |a few |a couple of )?(?:supplies|things|bits|stuff|bits and pieces)(?P<why> for (?:her|his|their|the) [a-z' -]+?)?\\\\s*:\\\\s*(?=(?:both )?the )\"",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_neither_nor40r": (
        "45119bf9741bbe79",
        ((), ("other",), False),
        (),
    ),
    "hltl.grounding._rewrites40r:_no_need40r": (
        "2319661dd7030995",
        ((), (" bother asking", "no need to "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_NO_NEED40R",
                (
                    "value",
                    '"^(?:no need to (?:ask|check|wait|worry|look)(?: (?:anyone|her|him|them|me|around|twice))?|(?:don\'t|do not|no need to) bother asking(?: (?:her|him|them|anyone))?)\\\\s*,\\\\s*(?=[a-z])"',
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_pair40r": ("274b63d300dc7e8f", ((), ("one each",), False), ()),
    "hltl.grounding._rewrites40r:_rather40r": ("4595fdba0b090259", ((), ("rather",), False), ()),
    "hltl.grounding._rewrites40r:_scarce40r": (
        "1516b91a75e7d12c",
        ((), ("have ", "there is ", "there's ", "we've "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_SCARCE40R",
                (
                    "value",
                    "\"^(?:we've (?:only )?got |we (?:only )?have |we've only |there's (?:only |just )?|there is (?:only |just )?)(?:the one|a single|one|just the one|only the one|only one|just one) (?P<x>[a-z]+(?: [a-z]+)?)\\\\s*,?\\\\s*(?:and|so|but)\\\\s+(?P<rest>.+)$\"",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites40r:_taking_so40r": ("d0969f5945dc0e14", ((), ("taking",), False), ()),
    "hltl.grounding._rewrites40r:_theirs40r": ("f1fa8291959029a4", (("'s",), (), False), ()),
    "hltl.grounding._rewrites40r:_whoever40r": (
        "f50b8823c72b57b8",
        ((), ("whichever", "whoever"), False),
        (),
    ),
    "hltl.grounding._rewrites40s:_been_and40s": (
        "27d40c94be7d9e06",
        ((), (" been ",), True),
        (
            (
                "_BEEN_AND40S",
                (
                    "pattern",
                    "^(?P<who>[a-z]+(?: [a-z]+)?)(?P<been>(?:'s| has) been [^,;:.!?]+?) and (?P<want>asked for|wants|needs|is after|fancies|could do with|would like) ",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites40s:_purpose40s": ("a01e8687a1af02c3", ((), ("for ",), False), ()),
    "hltl.grounding._rewrites40s:_thanks40s": (
        "d4bfa7d4b7be4f7a",
        ((), ("gives", "passes on", "says", "sends"), True),
        (
            (
                "_THANKS40S",
                (
                    "pattern",
                    "^(?P<who>[a-z]+(?: [a-z]+)?) (?:sends|says|passes on|gives) (?:(?:his|her|their) )?(?:thanks|cheers|thank you|love|regards|best wishes)(?: in advance)?\\s*[:;,.!-]+\\s*(?P<req>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites40s:_their_want40s": (
        "f0128722808e3402",
        (
            (),
            (" asked", " been ", " deserves ", " earned ", " was ", "asking for", "going on about"),
            True,
        ),
        (
            (
                "_THEIR_WANT40S",
                (
                    "pattern",
                    "(?P<sep>\\s*[,;]\\s*|(?<=[.!?])\\s+|\\s+[—–-]\\s+)(?:(?:and|as|because|cos|'cause)\\s+)?(?P<who>[a-z]+(?: [a-z]+)?)(?:(?:'s| has| had) been (?:on about|going on about|asking (?:for|about)|after|nagging (?:me )?(?:for|about)|waiting (?:for|on)|dreaming of|looking forward to|eyeing(?: up)?) (?:it|them)|(?:'s| has| had) earned (?:it|them)| earned (?:it|them)| deserves (?:it|them)| keeps (?:asking for|going on about) (?:it|them)| asked(?: for (?:it|them))? first| was (?:here |there )?first)(?P<tail>(?: (?:all (?:morning|day|afternoon|evening|week)(?: long)?|for ages|for weeks|since (?:the |her |his |a )?[a-z]+(?: [a-z]+){0,2}|after (?:the|her|his|a|an) [a-z]+(?: [a-z]+){0,3}|today|again|already|twice|first))*)\\s*[.!]?\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41:_alright_to41": (
        "91588a3298514cc0",
        ((), (" to ", "allowed"), False),
        (),
    ),
    "hltl.grounding._rewrites41:_asked_that41": (
        "0efeee7e4bcd7b33",
        ((), ("ask", "request"), False),
        (),
    ),
    "hltl.grounding._rewrites41:_courtesy41": (
        "733be3e892b91427",
        ((), (" for ", " mind ", "as ", "excuse", "forgive", "pardon"), True),
        (
            (
                "_COURTESY41",
                (
                    "compiled",
                    "pairs",
                    (
                        (
                            ",\\s*as (?:my|our|the|his|her|their|they|we|you|people|folk|one) (?P<w>[a-z' ]{0,40}?)(?:would say|'d say|says|say|used to say|would put it|puts it|put it|likes to say)(?: in [a-z]+)?\\s*,",
                            34,
                        ),
                        (
                            "(?:^|(?<=[.;!?])\\s*)(?:(?:i )?beg (?:your )?pardon|pardon me|excuse me|forgive me|(?:my )?apologies|sorry|so sorry)(?P<w> for (?:the|all the|this|that|my|our) [a-z]+(?: [a-z]+)?)\\s*,\\s*",
                            34,
                        ),
                        (
                            "(?:^|(?<=[.;!?])\\s*)(?:excuse|forgive|pardon) (?P<w>(?:the|all the|this|my|our) [a-z]+(?: [a-z]+)?)\\s*,\\s*",
                            34,
                        ),
                        (
                            "\\b(?P<w>(?:would|do) you) mind (?:ever so|so|very|terribly|awfully) much\\b",
                            34,
                        ),
                    ),
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites41:_going_way41": ("3fdedbf99c49da54", ((), ("'s way",), False), ()),
    "hltl.grounding._rewrites41:_let_take41": ("9b9e04303ca1b9ad", ((), ("take",), False), ()),
    "hltl.grounding._rewrites41:_lock_away41": ("e029b892d16cb3d5", ((), ("lock",), False), ()),
    "hltl.grounding._rewrites41:_mind_if_had41": (
        "f908dc5fe96e58c5",
        ((), ("mind if",), False),
        (),
    ),
    "hltl.grounding._rewrites41:_object_first41": ("8a17fcc866052a53", ((",",), (), False), ()),
    "hltl.grounding._rewrites41:_said_tag41": (
        "8bdb0ade8b1e8464",
        ((), (" asked", " insist", " reckon", " said", " says", " told"), False),
        (),
    ),
    "hltl.grounding._rewrites41:_said_want41": (
        "ae523439c44578c8",
        ((), ("mention", "reckon", "said", "says", "thin", "thought", "told"), False),
        (),
    ),
    "hltl.grounding._rewrites41:_sort_out41": (
        "0ecf31febf531b2f",
        ((), ("look after", "see ", "sort"), False),
        (),
    ),
    "hltl.grounding._rewrites41:_take_off41": ("4e017e8c372f6136", ((), ("take",), False), ()),
    "hltl.grounding._rewrites41:_want_idiom41": (
        "4ee398d8d6eda952",
        (
            (),
            (
                " bags",
                " for",
                " in ",
                " on about",
                " right arm",
                " set ",
                " sights ",
                "a claim",
                "anything",
                "asking",
                "begging",
                "entitled to",
                "first call",
                "first claim",
                "first dibs",
                "first pick",
                "glad",
                "grateful",
                "hankering ",
                "jump",
                "keen on",
                "leap",
                "nagging",
                "pestering",
                "pining ",
                "set on",
                "thankful",
                "the world",
            ),
            True,
        ),
        (
            (
                "_WANT_IDIOM41",
                (
                    "pattern",
                    "(?P<p>\\b[A-Za-z][\\w]*)(?P<idiom>(?: would|'d) (?:really |so |very |ever so )?be (?:glad|thankful|grateful) (?:of|for)|(?: is|'s) in (?:want|the market) (?:of|for)|(?: is|'s|'s been| has been) (?:really |so |very |dead |quite |absolutely |just |rather |pretty |awfully |ever so )?(?:set on|hungry for|thirsty for|starving for|famished for|parched for|ravenous for|yearning for|aching for|hankering (?:for|after)|hungering for|thirsting for|angling for|holding out for|entitled to|down for|(?:first |next )?in line for|first in the queue for|in the queue for|keen on|pining (?:for|after)|clamou?ring for|shouting for|yelling for|hollering for|gunning for)|(?: has|'s) set (?:his|her|their) (?:heart|sights) on|(?: has|'s)(?: got)? (?:his|her|their) sights (?:set )?on|(?: has|'s got|'s)(?: the)? (?:first call|first dibs|first claim|first pick|a claim) on|(?: has|'s) (?:bagsied|bagsed)|(?: would|'d) (?:happily |gladly )?give (?:anything|(?:his|her|their) right arm|the world) for|(?: would|'d) (?:happily |gladly )?(?:jump|leap) at|(?: has|'s got|'s) (?:a|such a|a real|a bit of a|a right) (?:yen|hankering|craving|hunger|thirst|longing|yearning) for|(?: keeps|'s been| has been| is|'s| kept) (?:going|banging|harping) on about(?: wanting| needing| having| getting)?|(?: keeps| kept) (?:asking|begging|pestering|nagging) for|(?: put|'s put| has put|'d put| had put) in (?:a word|a request|a bid|an order) for)(?= (?:the|that|this|those|these|both|a|an|some|his|her|their) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41:_will_do41": ("77e94526b0d66977", ((), (" do",), False), ()),
    "hltl.grounding._rewrites41r:_a_kind_said41r": (
        "b14a1bcff00c2f4c",
        ((" or the ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_all_n_of_them41r": (
        "cc42ceffcc1cbab5",
        ((), ("all ",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_corrected_then41r": (
        "e1aa9a59cb42bfaf",
        ((), ("no,",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_cue_run41r": (
        "7036149a075a9556",
        (
            (),
            (
                "ah",
                "correction",
                "daft me",
                "hang about",
                "hang on",
                "hold on",
                "hold up",
                "i tell a lie",
                "my bad",
                "my mistake",
                "no",
                "oh",
                "scratch that",
                "silly me",
                "sorry",
                "strike that",
                "wait",
                "what am i saying",
            ),
            True,
        ),
        (
            (
                "_CUE_RUN41R",
                (
                    "value",
                    "'\\\\s*[,;]\\\\s*(?P<run>(?:oh|ah|no|nope|wait|hang on|hang about|hold on|hold up|scratch that|strike that|silly me|daft me|my mistake|my bad|what am i saying|correction|sorry|i tell a lie)(?:[\\\\s,]+(?:oh|ah|no|nope|wait|hang on|hang about|hold on|hold up|scratch that|strike that|silly me|daft me|my mistake|my bad|what am i saying|correction|sorry|i tell a lie))*)\\\\s*[,;]?\\\\s+(?=[a-z])'",
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites41r:_everything_but41r": (
        "a5272ff6b3c0ea91",
        ((), ("all", "every", "lot"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_forget_after41r": (
        "d41ad8f600ec79fc",
        ((), ("bother", "forget", "leave out", "need", "never mind", "skip"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_fussy_between41r": (
        "bc3389ad2c415077",
        (("about", "between", "over"), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_instead_of_unwanted41r": (
        "1e4d9bb0c364faab",
        ((), ("away from", "instead", "reach of"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_just_those41r": (
        "fe94613fa6f7d432",
        ((), ("just", "nothing", "only", "that's"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_left_that_isnt41r": (
        "38c90db644e06074",
        ((), ("left", "over", "remain"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_left_to_you41r": (
        "90c9664330698bf8",
        (
            (),
            (
                "'ll do",
                "as you",
                "easy",
                "however",
                "let you",
                "mind which",
                "pick",
                "whichever",
                "will do",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites41r:_let_use41r": ("3da31606aac205e2", ((), ("let ",), False), ()),
    "hltl.grounding._rewrites41r:_no_wait41r": (
        "1c2204382f6389a3",
        ((" off",), (" to wait", " waiting", "hurry", "rush"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_NO_WAIT41R",
                (
                    "value",
                    '"^(?:there\'s |there is )?(?:nothing to wait (?:for|on)|no (?:call|reason) to wait(?: (?:for anyone|for anything|around|about))?|no waiting(?: around)?|no (?:rush|hurry)(?: either way)?|no point waiting(?: around)?)\\\\s*[,;:]\\\\s*(?=[a-z])"',
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites41r:_not_for_after41r": (
        "95db6de38f6845ac",
        ((" for ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_not_its41r": (
        "d383f9f43f10211b",
        ((), ("after", "asked for", "fancies", "is wanting", "needs", "wanted", "wants"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_NOT_ITS41R",
                (
                    "value",
                    "\"^(?:not|never mind(?: about)?|forget(?: about)?|leave|skip|scrap) (?P<x>the [a-z]+(?: (?!(?:that|who|which|person|mr|mrs|ms|miss|dr)\\\\b)[a-z]+)?)(?:,? (?:mind|mind you|though))?\\\\s*[,;:]\\\\s*(?:but )?(?:it's|it is) (?P<y>the [a-z]+(?: (?!(?:that|who|which|person|mr|mrs|ms|miss|dr)\\\\b)[a-z]+)?) (?:that )?(?P<p>[A-Za-z][\\\\w ]*?)(?:'s| is|'s been| has been)? (?:after|wants|needs|asked for|has asked for|'s asked for|wanted|is wanting|fancies|is after|'s after)(?P<rest>(?:\\\\s+[^,;.!?]+?)?)(?P<end>\\\\s*[.!]?)$\"",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites41r:_not_picky41r": (
        "412d2a121414c6ae",
        (("n't",), ("not",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_of_all41r": ("833c689a7cc1e57c", ((), ("all",), False), ()),
    "hltl.grounding._rewrites41r:_of_your_choosing41r": (
        "26236e1ff45509d1",
        ((), ("of your", "or other", "or the other"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_one_and_one41r": (
        "2d885eadfb2820dd",
        ((), ("one ", "single"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_one_going41r": ("fbfb79cce189754c", ((), ("one",), False), ()),
    "hltl.grounding._rewrites41r:_one_of_them_gets41r": (
        "a555530f1c6458eb",
        ((), ("one of",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_only_one_anyway41r": (
        "c3021e113ef8ff24",
        ((), ("only one",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_onto_with41r": ("75b68151b1b6cf6e", ((" with ",), (), False), ()),
    "hltl.grounding._rewrites41r:_out_on41r": ("a57d76491c3e0a87", ((" out ",), (), False), ()),
    "hltl.grounding._rewrites41r:_pair_listed41r": (
        "fb1ec7f96b764f51",
        ((" of them ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_pair_of41r": ("e6a3fede15345b56", ((), (" of ",), False), ()),
    "hltl.grounding._rewrites41r:_plain_simple41r": (
        "976117684249bee0",
        ((), ("simple", "that's"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_pronoun_again41r": (
        "7c489e12bbb4d05d",
        ((), ("no,",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_rather_than_first41r": (
        "8d2d02fe6053356b",
        ((), ("in place of", "rather than"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_said_already41r": (
        "dfcb5409c00a3554",
        (("already", "before", "earlier"), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_shared_out41r": ("4eb2532dfd048870", ((":",), (), False), ()),
    "hltl.grounding._rewrites41r:_so_long_as41r": (
        "8fed96a41a3742b5",
        (("long as", "provid"), (" not ",), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_start_again41r": (
        "d5f77c83d3569a38",
        ((), ("again", "over", "rephrase"), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_straight_to41r": ("3641eb0dc06b7a38", ((), ("no,",), False), ()),
    "hltl.grounding._rewrites41r:_the_one_for41r": (
        "fd3d459975bffd7e",
        ((" one ", "'s"), (), False),
        (),
    ),
    "hltl.grounding._rewrites41r:_turns_down41r": (
        "f55b01abdcd8f352",
        (
            (),
            (
                "care for",
                "fancy",
                "keen",
                "no ",
                "no need",
                "no use",
                "pass",
                "passing",
                "stand",
                "turned down",
                "without",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites41r:_whichever_free41r": (
        "629b2987c6b95172",
        ((" or ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites41s:_all_for41s": (
        "0e0f91492423c99b",
        ((), ("all ",), True),
        (
            (
                "_ALL_FOR41S",
                (
                    "pattern",
                    "(?P<head>(?:^|[.!?;,]\\s*)(?:it|that|this|they|these|those)(?:'s| is| are|'re) )all (?P<rest>for (?:the|a|an|his|her|their|our) (?P<what>[a-z][a-z' -]*?))\\s*(?P<end>[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41s:_errand41s": (
        "2a1d9ef0dc28bf4a",
        (
            (),
            (
                " is taking",
                " take",
                "'s taking",
                "cleaned",
                "cleared",
                "got ",
                "laid",
                "set",
                "sorted",
                "tidied",
                "wiped",
            ),
            True,
        ),
        (
            (
                "_DONE_TO41S",
                (
                    "pattern",
                    "^(?P<who>[a-z]+(?: [a-z]+)?)(?:'s| has) (?:got (?P<s1>(?:the|that) [a-z]+(?: [a-z]+)?) (?:sorted|cleared|wiped(?: down)?|tidied|cleaned|set|laid|done|ready)(?: out)?|(?:sorted|cleared|wiped(?: down)?|tidied|cleaned|set|laid) (?P<s2>(?:the|that) [a-z]+(?: [a-z]+)?))(?: already| now)?\\s*,?\\s*(?:and )?so,?\\s+(?P<req>\\S.*)$",
                    34,
                ),
            ),
            (
                "_TAKES_TO41S",
                (
                    "pattern",
                    "(?P<who>\\b[a-z]+(?: [a-z]+)?)(?:'s taking| is taking| can take| could take| will take|'ll take| takes| to take| may take| might take| take) (?P<what>[^,;:.!?]+?) (?P<to>(?:(?:home|off|back|away|round|over|along) )?to (?:the|his|her|their|a) (?P<where>[a-z][a-z' -]*?))(?=\\s*(?:[.,;:!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41s:_group_remark41s": (
        "0eddfd06d14a95d1",
        (
            (),
            (
                " with",
                "after",
                "need",
                "now",
                "seeing as",
                "seeing that",
                "use",
                "using",
                "want",
                "who",
            ),
            True,
        ),
        (
            (
                "_NOW_THAT41S",
                (
                    "pattern",
                    "(?P<sep>,?\\s+)(?:now that|now|seeing as|seeing that) (?P<said>(?:the|our|my|we)\\b[^,;:.!?]*?)\\s*(?P<end>[.!]?)\\s*$",
                    34,
                ),
            ),
            (
                "_THEIR_USE41S",
                (
                    "pattern",
                    "(?P<sep>\\s*[,;]\\s*|\\s+(?:-|—|–)\\s+|(?<=\\bplease)\\s+|(?<=\\bpls)\\s+|(?<=\\bthanks)\\s+)(?P<who>(?:the|our|my) [a-z]+(?: [a-z]+){0,2}?)(?:'s|'re|'ll| is| are| has| have| will| would)? ?(?:(?:be )?(?:done|finished|through) with|(?:be )?(?:want|need|use|wanting|needing|using|after)|want|need) (?:it|them|those|these)(?: (?:now|later|next|soon|after|afterwards|in a bit|tonight))?\\s*[.!]?\\s*$",
                    34,
                ),
            ),
            (
                "_WHO_IS41S",
                (
                    "pattern",
                    "(?P<sep>,\\s*)who(?P<rest>(?:'s| is| was| has| had)\\s[^,;:.!?]+?)\\s*(?P<end>[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41s:_middle_remark41s": (
        "f0125c909814623f",
        ((), (" from", "and"), True),
        (
            (
                "_FROM_DOING41S",
                ("pattern", "\\b(?P<from>(?:back|home|in) from) (?P<doing>[a-z]+ing)\\b", 34),
            ),
            (
                "_MIDDLE41S",
                (
                    "pattern",
                    ",\\s*(?P<said>(?:(?:he|she)(?:'s| is| has| was| had)|(?:his|her) [a-z]+)\\b[^,;:.!?]*?),\\s*(?P<next>and\\s+\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites41s:_occasion41s": (
        "e5edc16a08c3b7b6",
        ((), ("after ", "ahead of ", "before ", "during ", "following ", "since "), False),
        (),
    ),
    "hltl.grounding._rewrites41s:_placed_for41s": ("87c9942f57346803", ((), ("for ",), False), ()),
    "hltl.grounding._rewrites41s:_purpose41s": ("318eb8f9b5ed03c2", ((), ("for ",), False), ()),
    "hltl.grounding._rewrites41s:_trade41s": (
        "4065a34e5b8b3886",
        ((), (" and ", "the "), True),
        (
            (
                "_TRADE_AFTER41S",
                (
                    "pattern",
                    "(?P<to>\\b(?:for|to) )(?P<who>[a-z]+(?: [a-z]+){0,2}?) (?P<trade>the (?:[a-z]+ ){0,2}(?!(?:after|later|never|ever|over|under|rather|together|either|neither|other|another|whether|sooner|for|nor|or|per|thereafter|hereafter|ago)\\b)[a-z]+(?:er|or|ist|ian|man|men|woman|women|lady|ladies|smith|wright|wife|maker|hand|champion|champ|captain|chef|cook|fan|buff|nurse|lad|lass|guy|boss|rep|warden|keeper)s?)(?=\\s*(?:[.,;:!?]|$)|\\s+(?:and|then|please|pls|thanks|so)\\b)",
                    34,
                ),
            ),
            (
                "_TRADE_AND41S",
                (
                    "pattern",
                    "(?P<who>\\b(?:he|she)|^[a-z]+(?: [a-z]+){0,2}?|(?<=[,;:.!?] )[a-z]+(?: [a-z]+){0,2}?)(?:'s| is) (?:a|an|the) (?P<trade>(?:[a-z]+ ){0,2}(?!(?:after|later|never|ever|over|under|rather|together|either|neither|other|another|whether|sooner|for|nor|or|per|thereafter|hereafter|ago)\\b)[a-z]+(?:er|or|ist|ian|man|men|woman|women|lady|ladies|smith|wright|wife|maker|hand|champion|champ|captain|chef|cook|fan|buff|nurse|lad|lass|guy|boss|rep|warden|keeper)s?) and (?P<rest>[a-z][a-z']*)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42:_ask_forms42": (
        "c1f76170307d7b3a",
        (
            (),
            (" you", " you for", " you to", "bother", "from over ", "hassle", "to ask", "trouble"),
            True,
        ),
        (
            (
                "_ASK_FORMS42",
                (
                    "compiled",
                    "pairs",
                    (
                        (
                            "\\b(?:could|can|might|may) I (?:just )?(?:trouble|bother|ask) you to\\b",
                            34,
                        ),
                        (
                            "\\b(?:is it|would it be|will it be) (?:too much|a lot|much) (?:of a )?(?:bother|trouble|hassle|to ask)(?: for you)? (?:to|if you could)\\b",
                            34,
                        ),
                        (
                            "\\b(?P<ask>could|can|would|will) (?P<who>[A-Z][\\w]*(?: [A-Z][\\w]*)?) (?:trouble|bother) you for\\b",
                            34,
                        ),
                        (
                            "\\b(?P<ask>(?:could|would|will|can) you)(?: be (?:good|kind) enough to| be so (?:good|kind) as to)? (?:please )?see (?:that |to it that )?(?=[A-Z][\\w]*(?: [A-Z][\\w]*)? (?:gets|has|receives)\\b)",
                            34,
                        ),
                        ("\\s+from over (?:there|here|yonder)(?=\\s*(?:[,.;!?]|$))", 34),
                        (
                            "(?:^|(?<=[.;!?])\\s*)(?:while|when|whilst|since) you(?:'re| are) (?:on your feet|up|up and about|passing|going past|walking past|nearby|about)\\s*,\\s*|,?\\s+(?:while|when|whilst) you(?:'re| are) (?:on your feet|up|up and about|passing|going past|walking past)(?=\\s*[.!]*\\s*$)",
                            34,
                        ),
                    ),
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42:_cleft_want42": (
        "a6710e7f2fe20da5",
        ((), ("'tis ", "it is ", "it's ", "what "), False),
        (),
    ),
    "hltl.grounding._rewrites42:_confirm42": (
        "f5b3a1655a8d536b",
        ((), (" one", "that's it"), False),
        (),
    ),
    "hltl.grounding._rewrites42:_courtesy42": (
        "6826c4369fa9bbdd",
        (
            (),
            (
                " from ",
                "apologies",
                "beg pardon",
                "cheers",
                "excuse me",
                "forgive me",
                "hello",
                "i beg your pardon",
                "pardon me",
                "passed on",
                "passes on",
                "please",
                "says",
                "send",
                "sent",
                "sorry",
                "thank you",
                "thanks",
            ),
            True,
        ),
        (
            (
                "_COURTESY42",
                (
                    "compiled",
                    "single",
                    (
                        (
                            "^(?:(?:(?:good )?(?:evening|morning|afternoon)|hello|hi|hiya|hey|greetings),?\\s+(?:and\\s+)?)?(?:(?:so |terribly |awfully |very )?sorry|(?:my )?apologies|apologies|pardon me|excuse me|forgive me|beg pardon|i beg your pardon) (?:about|for) (?P<w>[^:;.!?]{1,80}?)(?:\\s*[:;.!?—–]\\s*|,\\s*but\\s+)",
                            34,
                        ),
                        (
                            "^(?:(?:with|and) )?(?:(?:many|much|warm|grateful|heartfelt|big|huge) )?(?:thanks|thank yous|gratitude|love|regards|best wishes|greetings|cheers)(?: (?:in advance|again))? from (?P<w>[^:;.!?]{1,80}?)\\s*[:;.!—–]\\s*",
                            34,
                        ),
                        (
                            "^(?P<w>(?:the|our|my|your|a|an) [a-z][a-z' ]{0,60}?|[A-Z][a-z]+(?: [A-Z][a-z]+)?) (?:sends|send|says|passes on|passed on|sent) (?:(?:his|her|their|its|warm|kind|best|fond) )?(?:regards|love|best|best wishes|thanks|apologies|greetings|hellos?|compliments)(?: to you| to you all| to all)?\\s*[:;.!—–]\\s*",
                            34,
                        ),
                        (
                            "^(?P<w>[A-Za-z][\\w'-]*(?: [A-Za-z][\\w'-]*)?),\\s*(?:which|that) (?:is|means|'s) (?:thanks|thank you|thank you very much|cheers|hello|please|sorry)(?: in (?:[A-Z][a-z]+))?(?:,\\s*(?:my|our|his|her|their) (?:first|mother|home|native) (?:language|tongue))?\\s*[.;:!—–]\\s*",
                            34,
                        ),
                    ),
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42:_elided_want42": ("d1caf98bf3934290", ((), (" and ",), False), ()),
    "hltl.grounding._rewrites42:_get_one42": ("30be8a22fb58c216", ((), (" one",), False), ()),
    "hltl.grounding._rewrites42:_left_behind42": ("def013d89a53f46a", ((), (" back",), False), ()),
    "hltl.grounding._rewrites42:_more_than42": (
        "249d92f125eb8743",
        ((), ("more than",), False),
        (),
    ),
    "hltl.grounding._rewrites42:_own_thing42": (
        "8e3dadf9fbc9e24d",
        ((), (" her ", " his ", " their "), False),
        (),
    ),
    "hltl.grounding._rewrites42:_people_order42": ("f1319ecaa9d532e0", ((), ("with ",), False), ()),
    "hltl.grounding._rewrites42:_possession42": ("5282a9081c8a3164", (("'s",), (), False), ()),
    "hltl.grounding._rewrites42:_proposal42": ("b428991f18b23d68", (("?",), (), False), ()),
    "hltl.grounding._rewrites42:_room_for42": (
        "03f371bca0711be1",
        ((), ("room", "space"), False),
        (),
    ),
    "hltl.grounding._rewrites42:_says_placed42": (
        "e6da253a3509ecdd",
        ((), ("reckon", "said", "say", "tells", "think", "told"), False),
        (),
    ),
    "hltl.grounding._rewrites42:_so_pronoun42": ("410acf1dbaa67a12", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites42:_so_run_on42": ("175dff4dd8409289", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites42:_that_is42": ("f1ad8e3d57327b21", ((), ("that is",), False), ()),
    "hltl.grounding._rewrites42:_would_help42": (
        "04bf4f55166b1a2c",
        (("'d ",), (" will ", " would "), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_all_but_first42r": (
        "ffe0c68925ffb744",
        (
            (),
            ("all the other things", "all the others", "anything", "everything", "the rest"),
            True,
        ),
        (
            (
                "_ALL_BUT_FIRST42R",
                (
                    "value",
                    "\"^(?:(?:apart from|except for|other than|aside from|besides|bar|save for|excepting) (?P<x>(?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?(?:(?:,| and) (?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?)*)\\\\s*,|leave (?P<x2>(?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?(?:(?:,| and) (?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?)*) (?:alone|be|out(?: of it)?|aside|where (?:it is|they are))\\\\s*[;,.:])\\\\s*(?:(?:everything|anything)(?: else)?|all the rest|the rest|all the other things|all the others)(?: (?:besides|but|except|other than) (?:it|them|that|those))?(?: (?:on offer|here|going|left|in the room|there is|you've got|we've got))?\\\\s*(?:(?:goes|can go|should go|is going) to (?P<p>(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+))|(?:is|are) (?:for )?(?P<p2>(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+))(?:'s)?|(?:for|to) (?P<p3>(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)))(?P<end>\\\\s*[.!]?)$\"",
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_count_again42r": (
        "8ca455d4c1001a26",
        ((), ("at once", "four", "in one go", "three", "together", "two"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_count_then_list42r": (
        "8d94b801ae835db5",
        ((), ("both", "four", "three", "two"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_courtesy42r": (
        "e06d8ab1b0bec055",
        ((), ("n't", "no", "not", "without"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_dont_mind42r": ("62baa985421b55f1", ((), ("mind",), False), ()),
    "hltl.grounding._rewrites42r:_either_way42r": (
        "10974f2cf1a67c1b",
        (
            (),
            (
                "all the same",
                "at any rate",
                "either way",
                "in any case",
                "one way or ",
                "whatever happens",
                "whichever way",
            ),
            True,
        ),
        (
            (
                "_EITHER_WAY42R",
                (
                    "value",
                    '"^(?:either way|whatever happens|in any case|one way or (?:another|the other)|all the same|whichever way|at any rate),\\\\s*(?P<rest>\\\\S.*?)(?:\\\\s+(?:in the end|eventually|at the end of the day|ultimately|when all\'s said and done))?(?P<end>\\\\s*[.!]?)$"',
                ),
            ),
            ("_F", ("value", "re.IGNORECASE")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_for_choice42r": (
        "7b6958c05137ac14",
        ((), (" or th", "one of the "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_FOR_CHOICE42R",
                (
                    "value",
                    "'^for (?P<p>(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)),\\\\s*(?P<x>(?:either )?(?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?(?: or (?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?)+|(?:any )?one of the [a-z]+s?)(?P<rest>(?:\\\\s*,[^.!?]*)?)(?P<end>\\\\s*[.!]?)$'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_just_one42r": (
        "697c761f858aa0dc",
        ((), ("her", "him", "them"), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_JUST_ONE42R",
                (
                    "value",
                    "'\\\\s*[;,]\\\\s*(?:so |and )?(?:just )?(?:take|give|bring|pass|hand|get) (?P<pro>him|her|them) (?:one|either|one of them|either of them|whichever)(?P<end>\\\\s*[.!]?)$'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_keep_saying42r": ("5f2ed219c2142a1c", ((), ("keep",), False), ()),
    "hltl.grounding._rewrites42r:_leave_all_but42r": (
        "e118a2aeddc8fee2",
        ((), ("leave ",), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_LEAVE_ALL_BUT42R",
                (
                    "value",
                    "'^leave (?:everything|it all|all of it|the lot)(?: else)?(?: (?:on|in) (?P<s>the [a-z]+(?: [a-z]+)?))? (?:where it is|as it is|be|alone)\\\\s*,?\\\\s*(?:except|but|apart from|bar|other than|except for|save) (?P<x>(?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\\\\b)[a-z]+)?)\\\\s*(?:,\\\\s*which|;\\\\s*(?:that|it)|:\\\\s*(?:that|it)|,\\\\s*(?:that|it)) (?P<v>goes|should go|needs to go|wants to go|can go|has to go|is to go) (?P<prep>in|on|into|onto) (?P<t>the [a-z]+(?: [a-z]+)?)(?P<end>\\\\s*[.!]?)$'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_negated_then42r": (
        "b0a415abfe23e4e8",
        ((), (" no ", "n't", "never", "not", "without"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_not_list_first42r": (
        "a82b5b354935c2e2",
        ((), ("forget", "never mind", "not"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites42r:_not_on42r": (
        "cb98e62de49d92dc",
        ((), (" not ", "n't"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_once_got42r": ("933ad0172bc11030", ((), ("once",), False), ()),
    "hltl.grounding._rewrites42r:_one_each42r": (
        "ccad153d3354e322",
        (
            (),
            ("ach person", "each", "everybody", "everyone", "very person", "verybody", "veryone"),
            True,
        ),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_ONE_EACH42R",
                (
                    "value",
                    "'\\\\s*,?\\\\s*(?:so |and )?(?:each of them|each one|everyone|everybody|they each|each)(?: of them)? (?:ends up with|end up with|gets|get|has|have|walks away with)(?: just| only)? (?:the )?one(?: thing| item| each)?(?P<end>\\\\s*[.!]?)$'",
                ),
            ),
            (
                "_ONE_EACH_FIRST42R",
                (
                    "value",
                    "'^(?:everybody|everyone|each person|every person) (?:gets|get|has|have|is getting|are getting|ends up with) (?:a single|one|just one|the one|only one) (?:item|thing)(?: each| here| apiece| this time)?\\\\s*:\\\\s*(?P<rest>\\\\S.*)$'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_only_one42r": ("4ff76ed5172482bf", ((), ("the one",), False), ()),
    "hltl.grounding._rewrites42r:_owned_mistake42r": (
        "6deda16f52a2f044",
        (
            (),
            (
                "correct",
                "hang on",
                "hold on",
                "ignore",
                "memory",
                "misspoke",
                "mistake",
                "mixed up",
                "muddled",
                "my bad",
                "no",
                "put that right",
                "slip",
                "what am i",
                "wrong",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites42r:_pronoun_i_mean42r": (
        "1e28e3dac2474735",
        ((), ("i mean",), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_respectively42r": (
        "c7d2d2fb41399bfe",
        ((), ("respectively",), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_role_group42r": (
        "5035ffcd4e0ef537",
        ((), ("a", "all ", "both", "the "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_ROLE_GROUP42R",
                (
                    "value",
                    "'(?<!\\\\bof )\\\\b(?:the (?P<n>two|three|four)|both(?: of the)?|all (?P<n2>two|three|four)(?: of the)?) (?P<r>[a-z]+s)\\\\b'",
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites42r:_single42r": (
        "573cf322507c635b",
        ((), ("single", "the one"), False),
        (),
    ),
    "hltl.grounding._rewrites42r:_things_here42r": (
        "cdfd578fbd060611",
        ((), ("of the", "with"), False),
        (),
    ),
    "hltl.grounding._rewrites42s:_as_for42s": ("baa6cd2966bac118", ((), ("as ",), False), ()),
    "hltl.grounding._rewrites42s:_doer_gets42s": (
        "aed3773c64c7d058",
        ((), ("bring", "fetch", "give", "hand", "pass", "send", "take"), True),
        (
            (
                "_DOER42S",
                (
                    "pattern",
                    "^(?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))(?:'s|\\s+is)\\s+(?P<words>[a-z]+ing\\b[^.;:!?,]*?)(?:,\\s*(?:so\\s+)?|;\\s*|\\s+so\\s+)(?P<rest>(?:(?:please|just|can you|could you)\\s+)?(?:hand|pass|give|bring|take|fetch|send)\\b[^.;:!?]*?)(?P<end>\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_for_surface42s": (
        "b0fcb279a0c93475",
        ((), (" for ",), False),
        (),
    ),
    "hltl.grounding._rewrites42s:_go_with42s": (
        "eb6e25e64c10439c",
        (
            (),
            (
                "dip in",
                "drink with",
                "eat with",
                "finish",
                "go in",
                "go on",
                "go with",
                "have with",
                "put in",
                "stir",
            ),
            True,
        ),
        (
            (
                "_GO_WITH42S",
                (
                    "pattern",
                    "(?P<sep>\\s*,?\\s+)to (?:go with|have with|eat with|drink with|dip in|finish off|finish|go in|put in|stir|go on) (?P<det>the|a|an|his|her|their|some) (?P<words>[a-z][a-z' -]*?)(?P<end>\\s*(?:,\\s*(?:please|thanks|ta|cheers))?\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_inferred42s": (
        "8970ebb01abded56",
        (
            (),
            (
                "angling for",
                "asking about",
                "asking for",
                "begging for",
                "eyeing",
                "eying",
                "gazing at",
                "gesturing",
                "glancing at",
                "grabbing at",
                "hinting about",
                "hinting at",
                "looking at",
                "nagging ",
                "nodding",
                "on about",
                "pestering ",
                "pointing",
                "reaching ",
                "staring at",
            ),
            True,
        ),
        (
            (
                "_INFERRED42S",
                (
                    "pattern",
                    "^(?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))\\s+(?:keeps|kept|has been|'s been|is|was)\\s+(?:(?:pointing|gesturing|nodding) (?:at|to|towards)|reaching (?:out )?for|eyeing(?: up)?|eying(?: up)?|looking at|staring at|gazing at|grabbing at|glancing at|asking about|going on about|on about|nagging (?:me |us )?(?:about|for)|pestering (?:me |us )?(?:about|for)|banging on about|asking for|begging for|angling for|hinting at|hinting about)\\s+(?P<obj>(?:the|that|those|this|these) [^,.;:!?]+?)\\s*[,;]?\\s+(?:(?:and|so)\\s+)?(?:(?:i|we)\\s+(?:think|reckon|guess|suppose|bet|imagine|expect|'d say|would say)\\s+|i'd say\\s+|(?:pretty sure|probably|clearly|obviously|i'm guessing|im guessing)\\s+)?(?:(?P<pron>he|she)(?:'d|d| would)?\\s+(?:like|love|want|wants|fancies|is after|'s after|needs)|let (?P<let>him|her) have|(?P<can>he|she) (?:can|may|should) have)\\s+(?:it|them|those|that|one)\\b(?P<tail>.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_little_one42s": (
        "fa81dfecb41b4eac",
        ((), ("the ",), True),
        (
            (
                "_LITTLE_ONE42S",
                (
                    "pattern",
                    "(?<=[,;] )the (?:little|wee|young|youngest|small) (?:one|un|'un)(?=(?:'s|\\s+(?:is|has|was|had))\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_lives_on42s": (
        "bb27d472b20ecb5b",
        (
            (),
            (
                "be kept",
                "be stored",
                "belong",
                "has a home",
                "have a home",
                "is kept",
                "is stored",
                "live",
                "stay",
            ),
            True,
        ),
        (
            (
                "_LIVES_ON42S",
                (
                    "pattern",
                    "(?P<open>\\bfrom now on,?\\s+)?(?P<obj>(?:the|that|this) [a-z]+(?: [a-z]+){0,2}?)\\s+(?:can|should|will|is to|'s to|is going to|has to|must)?\\s*(?:live|lives|belong|belongs|stay|stays|be kept|is kept|be stored|is stored|have a home|has a home)\\s+(?P<prep>on|in|at|inside|on top of|up on) (?P<surf>(?:the|that) [a-z][a-z ]*?)(?P<close>\\s+(?:from now on|for good|from today|permanently|for now|now))?(?=\\s*(?:[.,;!?]|$|\\s+(?:and|please)\\b))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_middle_state42s": (
        "718e29eca8d8e6ea",
        ((), (" so ",), False),
        (),
    ),
    "hltl.grounding._rewrites42s:_once_there42s": (
        "b10e4cf07c20ddb9",
        ((), (" head ", "as soon as ", "once ", "when "), False),
        (),
    ),
    "hltl.grounding._rewrites42s:_opening_occasion42s": (
        "ed07afb8430b2859",
        ((), ("after", "following", "since"), True),
        (
            (
                "_OPENING_OCCASION42S",
                (
                    "pattern",
                    "^(?:ever\\s+)?(?P<prep>since|after|following)\\s+(?:(?P<det>his|her|their|the|a)\\s+)?(?P<tail>[a-z].*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_orders_stand42s": (
        "2fb45361c7f763f2",
        ((), ("before", "earlier", "i gave ", "last time", "this morning", "yesterday"), True),
        (
            (
                "_ORDERS_STAND42S",
                (
                    "pattern",
                    "^(?:(?:the|my|our|those|all the|any) )?(?:orders|instructions|requests|plans|jobs) (?:from (?:earlier|before|this morning|yesterday|last time)|i gave (?:you )?(?:earlier|before)) (?:still )?(?:stand|apply|hold|go|count)\\b,?\\s*(?:[.;:]\\s*)?(?:(?:and|so|but)\\s+)?",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_pastime_place42s": (
        "97e93fb4f9fba884",
        ((), ("after", "before", "following", "since"), True),
        (
            (
                "_PASTIME_PLACE42S",
                (
                    "pattern",
                    "\\b(?P<occ>(?:after|before|since|following) (?:his|her|their|the|a) [a-z]+(?: [a-z]+)?) (?P<place>(?:on|at|in|round|around|down|by|along|up) (?:the|a) [a-z]+(?: [a-z]+)?)(?=\\s*(?:[.,;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_speaker_doing42s": (
        "43a8dd4578339cfc",
        ((), ("i am", "i'm", "i've", "im ", "ive ", "we are", "we're", "we've"), False),
        (),
    ),
    "hltl.grounding._rewrites42s:_state_and42s": ("6650c0292b860217", ((), (" and ",), False), ()),
    "hltl.grounding._rewrites42s:_thinking42s": (
        "334ee065518e1f37",
        ((), (" thinking",), True),
        (
            (
                "_THINKING42S",
                (
                    "pattern",
                    "^(?P<lead>(?:(?:ok|okay|so|right|well|now|um|erm)\\s*,?\\s+)*)(?:i|we)(?: was| were|'m|'re|m| am| are)? thinking,?\\s+(?:that\\s+|maybe\\s+|perhaps\\s+)*(?=(?:the|that|this|those|these) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_to_find42s": (
        "7ff9070eb06c0ebb",
        ((), ("for ",), True),
        (
            (
                "_TO_FIND42S",
                (
                    "pattern",
                    "(?P<for>\\bfor (?:the|a|our|my|whoever|whichever) [a-z][a-z' -]*?) to (?:find|use|collect|pick up|grab|see|sort|deal with|have)(?: (?:it|them))?(?=\\s*(?:[.,;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites42s:_while_doing42s": (
        "5f8dc0705ac27c2c",
        ((), ("while ",), True),
        (
            (
                "_WHILE42S",
                (
                    "pattern",
                    "(?P<sep>\\s*,?\\s+)while (?P<pron>he|she)(?:'s|\\s+is|\\s+[a-z]+(?:s|ed))\\b(?P<words>[^.;:!?,]*?)(?P<end>\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43r:_any_except43r": ("fc60d35efd834414", ((), ("any",), False), ()),
    "hltl.grounding._rewrites43r:_any_will_do43r": (
        "40918ca87594908f",
        ((), ("anything", "bothered", "fussed", "fussy", "mind", "whatever"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_apiece43r": (
        "096801ce45cc0ce7",
        ((), ("apiece", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_bar_first43r": (
        "4fe50a6a35f119b3",
        ((), ("all", "everything", "lot", "rest"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_changed_order43r": (
        "d6ba4ae9728e8a95",
        ((), ("chang", "now", "rather", "sooner", "swapp", "switch"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_counted_list43r": (
        "dc9654f9ab43b220",
        ((), ("both", "of them", "pair", "requests", "set of", "things"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_if_there_is43r": ("a1c5a774419a124f", ((), ("if ",), False), ()),
    "hltl.grounding._rewrites43r:_mid_sized43r": (
        "0bff4ea96885d8a6",
        ((), ("sized",), False),
        (
            ("_F", ("value", "re.IGNORECASE")),
            ("_MID_SIZED43R", ("value", "'\\\\b(?:middle|mid|medium)[- ]?sized\\\\b'")),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites43r:_need_without43r": (
        "04c6a3cb3baba3f9",
        ((), ("nothing", "without"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_never_asked43r": (
        "42b30dadae238b12",
        ((), (" not ", "n't", "never"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_no_need_wait43r": (
        "b0623b4bcf7877ac",
        ((), ("n't", "no ", "not"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_not_idiom43r": (
        "88a57fbf4ae0107e",
        (
            (),
            (
                "abide",
                "bothered",
                "care",
                "done",
                "down",
                "drink",
                "eat",
                "enough",
                "face",
                "fancy",
                "fed up",
                "fill",
                "finished",
                "fussed",
                "gone",
                "like",
                "near",
                "no need",
                "no to",
                "no use",
                "nose",
                "sick",
                "stand",
                "stomach",
                "thank",
                "through",
                "tired",
                "touch",
                "turn",
                "use",
                "will not be",
                "won't be",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites43r:_nothing_more43r": (
        "4e6b6da4c29c8501",
        ((), ("no more", "not a", "nothing"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_one_said43r": (
        "baf56ccfda8930b6",
        ((), ("lone", "one", "single", "sole", "solitary"), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_only_the_one43r": ("99039dc9628ba1e4", ((), ("one",), False), ()),
    "hltl.grounding._rewrites43r:_other_way43r": (
        "42d8dcc87e41da5f",
        ((), ("other way",), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_said_wrong43r": (
        "a9101b1256885d46",
        ((), ("did i", "i said", "not "), False),
        (),
    ),
    "hltl.grounding._rewrites43r:_slip_cue43r": (
        "c246ba01977ade50",
        (
            (),
            (
                "back up",
                "change of plan",
                "forget",
                "mis",
                "mixed",
                "muddled",
                "my bad",
                "my error",
                "my mistake",
                "not it",
                "not right",
                "rewind",
                "scrap",
                "scratch",
                "silly me",
                "start",
                "strike",
                "take that",
                "wrong",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites43r:_to_hand43r": (
        "9f4b4739c1ad3ed4",
        ((), ("whatever", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites43s:_after_spell43s": (
        "e02e9ba8ac74aaa3",
        ((), ("after", "following"), True),
        (
            (
                "_SPELL43S",
                (
                    "pattern",
                    "^(?:after|following) (?:a|an|the|his|her|their|that) (?:(?:long|hard|busy|whole|full|tough|rough|gruelling|hot|cold|wet|late|early|heavy|endless|solid) ){0,2}(?:morning|day|afternoon|evening|night|week|shift|stint|spell|stretch|session|hour|hours|weekend|fortnight|month|lesson|practice)(?P<place> (?:on|at|in|out|up|down|over|round|behind|under) [^.;:!?,]{1,40}?),\\s*(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_and_takes43s": ("12be28bb97a07700", ((), ("take",), False), ()),
    "hltl.grounding._rewrites43s:_claimed_by43s": (
        "fe4da5a8b72ec140",
        (
            (),
            (
                "bagged",
                "booked",
                "called dibs on",
                "claimed",
                "earmarked",
                "put by",
                "reserved",
                "set aside",
                "spoken for",
            ),
            True,
        ),
        (
            (
                "_CLAIMED43S",
                (
                    "pattern",
                    "(?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?)(?P<be>'s|'re| is| are| was| were)(?: been)? (?:spoken for|claimed|bagged|reserved|booked|earmarked|called dibs on|put by|set aside) (?:by|for) (?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_found_person43s": (
        "44b8f9bf60c56ebe",
        ((), ("where",), True),
        (
            (
                "_FOUND43S",
                (
                    "pattern",
                    "^(?:(?:right|ok|okay|now|so|um|erm|er|hmm)\\s*,?\\s+)*where(?:'s| is) (?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))\\s*(?:\\.\\.\\.|…|\\?|,|-|–|—)\\s*(?:(?:ah|oh|aha|ah yes|right|ok|okay)\\s*,?\\s*)?(?:there (?:he|she) is|there|over there|found (?:him|her)|here (?:he|she) (?:is|comes))\\s*[.!,;…]*\\s+(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_go_with_it43s": (
        "deda879f0f04ca78",
        (
            (),
            (
                "drink with",
                "eat with",
                "go along with",
                "go alongside",
                "go with",
                "have with",
                "match",
                "use with",
            ),
            True,
        ),
        (
            (
                "_GO_WITH_IT43S",
                (
                    "pattern",
                    "(?P<sep>\\s*,?\\s+)to (?:go with|go alongside|go along with|have with|eat with|drink with|use with|match) (?:it|them|that|those|the first|the other)(?P<end>\\s*(?:,\\s*(?:please|thanks|ta|cheers))?\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_height43s": (
        "51a3d2c24e889c9a",
        ((), ("in", "on"), True),
        (
            (
                "_HEIGHT43S",
                (
                    "pattern",
                    "\\b(?:high up|up high|way up|right up|high|up|well up|low down|down low|right down)\\s+(?:on top of|on|onto|in|into|up on)\\s+(?=(?:the|that|this) )",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_in_with43s": (
        "fd714a2ecd47b6c8",
        ((), ("alongside", "beside", "next to", "with"), True),
        (
            (
                "_IN_WITH43S",
                (
                    "pattern",
                    "\\b(?P<prep>in|on|onto|into|up) (?:there )?(?:with|alongside|beside|next to) (?:it|them|that|those)\\b(?! (?:one|ones)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_liking_remark43s": (
        "ed4050446332938f",
        ((), (" he", " she"), False),
        (),
    ),
    "hltl.grounding._rewrites43s:_now_over43s": (
        "77b9ede9eacd53c4",
        ((), ("now ",), True),
        (
            (
                "_NOW_OVER43S",
                (
                    "pattern",
                    "(?P<sep>\\s*,?\\s+)now (?:that )?(?:(?P<p1>his|her) (?P<what>[a-z][a-z -]{1,40}?)(?:'s|\\s+is|\\s+has)\\s+(?:over|done|finished|ended|out of the way|wrapped up|been and gone)|(?P<p2>he|she)(?:'s|\\s+is|\\s+has)\\s+(?:back from|done with|finished|through with|(?:got )?out of) (?:his|her) (?P<what2>[a-z][a-z -]{1,40}?))(?P<end>\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_one_for43s": (
        "032176e6cf8ba6a5",
        ((), ("the ",), True),
        (
            (
                "_ONE_FOR43S",
                (
                    "pattern",
                    "(?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))(?:'s|\\s+is)\\s+the (?:one|person|lady|man|woman|fella|girl|boy|lad|chap|patient|one person) (?:(?:that |who |whom )?(?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?) (?:is|are|'s|'re) (?:for|meant for|going to|headed for)|(?:who|that) (?:gets|wants|needs|asked for|is getting|should get) (?P<y>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?))(?=\\s*(?:[.,;!?]|$|\\s+(?:and|please|thanks)\\b))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_opening_doer43s": (
        "9794875bd353848f",
        ((), ("ing",), True),
        (
            (
                "_OPENING_DOER43S",
                (
                    "pattern",
                    "^(?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))(?:'s|\\s+is)\\s+(?P<words>[a-z]+ing\\b[^.;:!?,]*?)(?:\\s*[;,.]\\s*(?:so\\s+)?|\\s+so\\s+)(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_placed_aside43s": (
        "3f2f76064f03ce18",
        ((), ("away from ", "can not", "can't", "cannot", "couldn't", "out of ", "won't"), True),
        (
            (
                "_OUT_OF_REACH43S",
                (
                    "pattern",
                    "(?P<sep>\\s*,?\\s*)(?:(?:where|so) (?P<who>[^.;:!?,]{1,40}?) (?:can't|cannot|can not|won't|couldn't) (?:get at|get to|reach|chew|grab|knock|touch|nick|pinch|see|find|spill|break|get hold of|mess with|eat) (?:it|them)|out of (?:the )?(?:sight|reach|way|harm's way)(?: of (?P<of>[^.;:!?,]{1,40}?))?|(?:safely )?away from (?P<from>(?:the|our|my|his|her|those) [^.;:!?,]{1,40}?))(?P<end>\\s*[.!?]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_placed_for43s": ("537cf8ea7fbb4008", ((), (" for ",), False), ()),
    "hltl.grounding._rewrites43s:_priority43s": (
        "b0a658bf3f82d735",
        (
            (),
            (
                "ahead of anything",
                "ahead of everything",
                "before all else",
                "before anything else",
                "before everything else",
                "first",
                "top of the list",
            ),
            True,
        ),
        (
            (
                "_PRIORITY43S",
                (
                    "pattern",
                    "(?P<x>(?:(?:the|that|this)|(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+)'s) [a-z]+(?: [a-z]+)?) (?:comes?|goes|go|should come|should go|ha(?:s|ve) to come|ha(?:s|ve) to go|needs? to come|needs? to go|is|are|must come|must go)\\s+(?:before anything else|before everything else|before all else|first of all|first|top of the list|ahead of everything(?: else)?|ahead of anything(?: else)?)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_run_on_wants43s": (
        "919f0289af43948c",
        (
            (),
            (
                "'d like",
                "after",
                "asked for",
                "could do with",
                "could use",
                "fancies",
                "gets",
                "getting",
                "having",
                "needs",
                "wants",
                "would like",
                "would love",
            ),
            True,
        ),
        (
            (
                "_WANTER43S",
                (
                    "pattern",
                    "(?<=[a-z]) (?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))(?:'s (?:after|having|getting)| (?:wants|needs|would like|would love|'d like|fancies|is after|is having|gets|could use|could do with|has asked for|asked for))\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_so_reason43s": ("536e17784ebf8bff", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites43s:_spot_for43s": (
        "e366a96da710684c",
        ((), ("for ",), True),
        (
            (
                "_SPOT_FOR43S",
                (
                    "pattern",
                    "(?:^|(?<=[.;!?] )|(?<=, )|(?<=\\band ))(?P<s>(?:the |that )?[a-z]+(?: [a-z]+)?)(?:(?:'s|\\s+is)\\s+(?:the|a|its|their) (?:(?:right|best|proper|usual|only) )?(?:spot|place|home|place to go|place to put|one)|(?P<first>\\s+first)?,)\\s+for (?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?)(?=\\s*(?:[.,;!?]|$|\\s+(?:and|then|please)\\b))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites43s:_whose_after43s": (
        "653fcf6ac733a49d",
        ((), ("'s",), True),
        (
            (
                "_WHOSE43S",
                (
                    "pattern",
                    "(?:^|(?<=[.;!?] ))(?P<x>(?:(?:the|that|this|those|these) )?[a-z]+(?: [a-z]+)?)(?P<first> first)?\\s*[.;]\\s+(?:(?:that's|that is|it's|it is|they're|they are|those are|that one's)\\s+)?(?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))'s\\s*(?P<end>[.;!]|$)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites44:_all_state44": ("0213513e4ac39497", ((), (" all ",), False), ()),
    "hltl.grounding._rewrites44:_ask_forms44": (
        "0375febc065703a3",
        (
            (),
            (
                " be so ",
                " it be ",
                " obliged if ",
                " way ",
                "be a bother",
                "be a pain",
                "bother you",
                "butt in",
                "disturb you",
                "ends up with",
                "gets hold of",
                "interrupt",
                "spare ",
                "thanks",
                "winds up with",
            ),
            True,
        ),
        (
            (
                "_ASK_FORMS44",
                (
                    "compiled",
                    "pairs",
                    (
                        (
                            "\\b(?P<ask>could|can|would|will) you (?:just )?spare (?:a|one|half a) (?:minute|moment|sec|second|mo|tick|jiffy)(?: or two)? to\\b",
                            34,
                        ),
                        (
                            "\\b(?:would|will) it be (?:a|too much of a|much of a|a real) (?:pain|bother|hassle|nuisance|faff|drag|chore) (?:for you )?to\\b",
                            34,
                        ),
                        (
                            "\\b(?P<ask>(?:could|can|would|will) you (?:please )?)(?:make sure|see to it that|ensure) (?P<p>[A-Za-z][\\w]*(?: [A-Za-z][\\w]*)?) (?:ends up with|winds up with|gets hold of)\\b",
                            34,
                        ),
                        (
                            "^(?:(?:I'd|I would|we'd|we would) be )?(?:much|most|very|greatly|ever so) obliged if (?P<p>[A-Za-z][\\w]*(?: [A-Za-z][\\w]*)?) (?:ended up with|could have|got|could get|had|were given|was given)\\b",
                            34,
                        ),
                        ("^if you(?:'d| would| could) be so (?:good|kind) as to\\b", 34),
                        (
                            "^(?:(?:er|erm|um|uh|oh)\\s*,?\\s*)?(?:sorry\\s*,?\\s*)?(?:I )?(?:hate|don't mean|don't want) to (?:interrupt|bother you|butt in|disturb you|be a pain|be a bother),?\\s*but\\s+",
                            34,
                        ),
                        ("\\b(?:make|find|wend) (?:its|their) way (?:over |across )?to\\b", 34),
                        (
                            "^(?:with (?:many |grateful |warm |all |my |our )?thanks(?: in advance)?),\\s*",
                            34,
                        ),
                    ),
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites44:_body_state44": ("38b9aa9ec76eca8b", (("'s ",), (), False), ()),
    "hltl.grounding._rewrites44:_cleft_tail44": (
        "57c8363934b3c895",
        ((), (" thing", " what "), False),
        (),
    ),
    "hltl.grounding._rewrites44:_cleft_time44": ("0fd31785a250a3c4", ((), (" is ",), False), ()),
    "hltl.grounding._rewrites44:_courtesy44": (
        "7f7e91ae480ef364",
        (
            (),
            (
                " respect",
                "if i may",
                "it is",
                "it means",
                "it's",
                "language",
                "respectfully",
                "thank you",
                "thanking you",
                "thanks",
                "that is",
                "that's",
                "tongue",
                "which is",
                "which means",
                "word",
            ),
            True,
        ),
        (
            (
                "_COURTESY44",
                (
                    "compiled",
                    "single",
                    (
                        (
                            "^(?P<w>[A-Za-z][\\w'-]*(?: [A-Za-z][\\w'-]*)?),\\s*(?:(?:friend|robot|machine|mate|pal|buddy|love|dear|my friend|robots|folks|you),\\s*)?(?:that's|that is|which is|which means|it's|it is|it means)(?: (?:just|basically|how you say))? (?:[A-Z][a-z]+ for|(?:the )?[A-Z][a-z]+ (?:word )?for) (?:'(?:thanks|thank you|cheers|hello|hi|please|sorry|good morning|greetings)'|(?:thanks|thank you|cheers|hello|hi|please|sorry|good morning|greetings))(?:,\\s*(?:more or less|roughly|sort of|kind of))?\\s*[.;:!—–]\\s*",
                            34,
                        ),
                        (
                            "^(?P<w>[A-Za-z][\\w'-]*)(?:,\\s*(?:friend|robot|machine|mate|pal|buddy|love|dear|my friend|robots|folks|you))?,?\\s*[—–]\\s*(?P<a>[^—–]{1,90}?\\b(?:word|words|language|tongue|thanks|thank you)\\b[^—–]{0,30}?)\\s*[—–]\\s*",
                            34,
                        ),
                        (
                            "^(?:with (?:all )?(?:due|the greatest|great) respect|respectfully|if I may)(?:,\\s*|\\s+)(?:(?:friend|robot|machine|mate|pal|buddy|love|dear|my friend|robots|folks|you),\\s*)?(?P<w>)",
                            34,
                        ),
                    ),
                ),
            ),
            (
                "_THANKING44",
                (
                    "pattern",
                    ",?\\s*thanking you(?: (?:kindly|in advance|muchly|so much|very much))?\\s*(?P<end>[.!]*)\\s*$",
                    34,
                ),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites44:_described44": (
        "fc1fc79be3b9a96a",
        (
            (),
            (
                "bring",
                "get",
                "give",
                "hand",
                "pass",
                "place",
                "pop",
                "put",
                "return",
                "send",
                "stick",
                "take",
            ),
            True,
        ),
        (
            (
                "_DESCRIBED44",
                (
                    "pattern",
                    "^(?P<x>(?:those|these|the|that|this) [a-z]+(?: [a-z]+)?)(?: (?:is|are|'re|'s) the (?:one|ones))? (?:that |which )?(?P<p>[A-Z][\\w]*(?: [A-Z][\\w]*)?) (?P<v>left|left out|brought|brought in|knocked|dropped|put down|had|bought|got|took|spilt|spilled|lost|forgot|abandoned|was using|was eating|opened)\\b(?P<d>[^,;.]*?)(?:,\\s*(?:so\\s+)?|\\s*[;:]\\s*|\\s+so\\s+)(?P<rest>(?:please )?(?:stick|put|pop|place|give|hand|pass|take|bring|return|send|get) (?:it|them)\\b.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites44:_ditto44": ("b450aaa073728d54", ((), ("ditto",), False), ()),
    "hltl.grounding._rewrites44:_fronted_said44": ("beb0e7a3b05ecec7", ((",",), (), False), ()),
    "hltl.grounding._rewrites44:_go_down44": (
        "56fce23abd8a878e",
        (("'d ",), (" will ", " would "), False),
        (),
    ),
    "hltl.grounding._rewrites44:_it_named44": ("0ddc3cdae8b2e197", ((), ("it ",), False), ()),
    "hltl.grounding._rewrites44:_kind_want44": (
        "12fc923c70113916",
        ((), ("bite", "drink", "eat", "munch", "nibble", "snack", "water"), False),
        (),
    ),
    "hltl.grounding._rewrites44:_on_body44": (
        "58c208a949417051",
        ((), (" her ", " his "), False),
        (),
    ),
    "hltl.grounding._rewrites44:_seeing_as44": (
        "54718522a46ccf59",
        ((), ("being", "seeing"), False),
        (),
    ),
    "hltl.grounding._rewrites44:_spilt44": (
        "8b42ff6fb4473af8",
        ((), (" and ",), True),
        (
            (
                "_SPILT44",
                (
                    "pattern",
                    "^(?P<p>[A-Za-z][\\w]*(?: [A-Za-z][\\w]*)?) (?:has |'s |just )?(?:spilt|spilled|knocked over|upset|splashed|slopped|dribbled|dropped) (?P<w>(?:his|her|their|some|a|an) [a-z]+(?: [a-z]+)?(?: (?:everywhere|all over (?:the floor|the place|himself|herself)|on the floor))?) and (?:wants|needs|would like|'d like|could use|could do with|is after|'s after) (?P<x>(?:the|a|an|some) [a-z]+(?: [a-z]+)??)(?: to (?:mop|wipe|clean|dry|soak|sponge)(?: (?:it|that|them))?(?: up)?)?(?P<end>\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites44:_want_words44": (
        "ec298a23a3698638",
        ((), (" about ", " for ", " of "), False),
        (),
    ),
    "hltl.grounding._rewrites44:_why_not44": ("0b029edc8a06bd6e", ((), ("why",), False), ()),
    "hltl.grounding._rewrites44r:_after_cue44r": (
        "d2bd9a744cf284af",
        ((), ("know what", "misspoke there", "second thought", "think"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_all_bar44r": (
        "81ff6779fef47dec",
        ((), ("apart", "bar", "but", "except", "save"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_any_of_them44r": (
        "5c4d1a73aa8bdb8b",
        ((), ("any", "either"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_deserves44r": (
        "3c0009c3ee03e1c2",
        ((), ("deserve", "earned"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_either_suits44r": (
        "fc4e4e86f274dcf8",
        ((), ("do ", "does ", "fine", "keeps", "matter", "odds", "please", "suit"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_either_those44r": (
        "1c61e098a5368b32",
        ((), (" of",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_fine_for44r": (
        "fb1139293e679f92",
        ((), (" am", " are", "'ll", "'m", "'re"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_grab_first44r": (
        "f26372862c62f070",
        ((), ("whichever",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_had_one44r": ("988c2ca38609cb28", ((), ("already",), False), ()),
    "hltl.grounding._rewrites44r:_is_all44r": ("edbb1ce31aebeb20", ((), (" is all ",), False), ()),
    "hltl.grounding._rewrites44r:_leaving44r": ("ed6088bb28e9f602", ((), ("leaving",), False), ()),
    "hltl.grounding._rewrites44r:_lone_going44r": (
        "0be7286130089913",
        ((), ("there",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_no_for44r": (
        "d46b73cbeb0e69e1",
        ((), ("no",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_not_allowed44r": (
        "4159065e6ef7ba79",
        ((), ("allowed", "meant", "supposed"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_not_aside44r": (
        "b29166be2217e8e9",
        ((), (", and not ", ", not "), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_not_hers44r": ("597bd0b8b2db793c", ((), (" not ",), False), ()),
    "hltl.grounding._rewrites44r:_not_want_remark44r": (
        "f60a371fe5314ab3",
        ((), (" no ", " want ", "n't ", "not "), True),
        (
            ("_F", ("value", "re.IGNORECASE")),
            (
                "_NOT_WANT_REMARK44R",
                (
                    "value",
                    '"^(?P<head>(?P<p>(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)) (?:doesn\'t|does not) want (?P<x>(?:(?:the|that|this|those|these|any) )?[a-z]+(?: (?!(?:after|at|for|to|with|from|since|because|as|on|in|so|and|or|but|is|are|was|were|be)\\\\b)[a-z]+)?))(?P<rest>\\\\s*[,;].+?)(?P<end>\\\\s*[.!]?)$"',
                ),
            ),
            (
                "_not_wanted39r",
                ("guarded", "hltl.grounding._rewrites39r:_not_wanted39r", "93a64d0c1b9c7e2c", ()),
            ),
            ("re", ("module", "hltl.grounding.gate")),
        ),
    ),
    "hltl.grounding._rewrites44r:_one_thing_but44r": (
        "5654e262080d52b6",
        ((), ("one ",), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_only_allowed44r": (
        "57d1aa458bd07a20",
        ((), ("only",), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_other_of44r": ("5e8cc56fbd7935f5", ((), ("other",), False), ()),
    "hltl.grounding._rewrites44r:_out_of44r": ("d86598bee9d6609f", ((":",), (), False), ()),
    "hltl.grounding._rewrites44r:_reason_fix44r": (
        "8b91bc13d1a53d54",
        ((), ("correction", "hang ", "hold on", "mistake", "no", "sorry", "wait"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_said_leave44r": (
        "d167d508e0a1b0df",
        ((), ("said", "says", "told me"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_skip_and44r": (
        "79508fec302c6ebb",
        ((), ("bother", "forget", "hold off", "leave out", "never mind", "pass on", "skip"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_stay_rest44r": (
        "1571a3fa821aaac6",
        ((), ("else", "other things", "rest"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites44r:_stays_out44r": (
        "aa3c1db15a4aeb73",
        ((), ("remain", "stay"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_up_for_grabs44r": (
        "d776a78f986e5ba7",
        ((), ("begging", "grabs", "spare"), False),
        (),
    ),
    "hltl.grounding._rewrites44r:_which_is_n44r": ("2234dfec69aa9841", ((), ("which",), False), ()),
    "hltl.grounding._rewrites44s:_after_end44s": (
        "490c4472505fc94e",
        ((), ("after", "last of all"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_after_her44s": (
        "7d9355516c432e85",
        ((), ("after h", "following h"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_asked_if44s": ("abcaec3cf785ec45", ((), ("asked",), False), ()),
    "hltl.grounding._rewrites44s:_back_from44s": (
        "2fc65f97901008a4",
        ((), ("from", "off to"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_before_mine44s": (
        "104a2a748213d674",
        ((), ("before",), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_done_next44s": ("b61a335af1ce1b04", ((), ("next",), False), ()),
    "hltl.grounding._rewrites44s:_done_with44s": (
        "84bd4741cfd8df56",
        ((), ("done", "finished"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_gapped44s": (
        "603bb1f433ad71ee",
        (
            (),
            (
                " after",
                "a must for",
                "aching for",
                "asked for",
                "asking for",
                "begging for",
                "called ",
                "could ",
                "craving",
                "crying out for",
                "deserve",
                "desperate for",
                "dying for",
                "earned",
                "eyeing",
                "eying",
                "famished",
                "fanc",
                "gasping for",
                "got to have",
                "hungry",
                "itching for",
                "keen on",
                "longing for",
                "need",
                "on about",
                "owed",
                "parched",
                "peckish",
                "pining for",
                "put in for",
                "ravenous",
                "set on",
                "starving",
                "thirsty",
                "want",
                "would ",
            ),
            True,
        ),
        (
            (
                "_WANT_SAID41S",
                (
                    "pattern",
                    "\\b(?:needs?|needed|wants?|wanted|wanting|would (?:like|love|kill for|be glad of)|could (?:do with|use|murder)|fanc(?:y|ies)|(?:'s|is|was|been|are|were) after|asking for|asked for|begging for|on about|eyeing|eying|set on|heart set on|gasping for|dying for|desperate for|crying out for|longing for|itching for|aching for|pining for|hankering after|craving|a must for|got to have|in want of|in need of|put in for|called (?:for )?(?:it|them)|keen on|owed|deserves?|earned|hungry|thirsty|starving|parched|peckish|famished|ravenous)\\b(?! to (?:go|be|get|come|move|end up|head|wait|stay|have it|have them)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites44s:_greeting44s": (
        "72ebaef87cee8b69",
        (
            (),
            (
                "afternoon",
                "all right",
                "alright",
                "cheers",
                "evening",
                "hello",
                "hey",
                "hi",
                "howdy",
                "morning",
            ),
            True,
        ),
        (
            (
                "_GREETING44S",
                (
                    "pattern",
                    "^(?:good )?(?:morning|afternoon|evening|hi|hello|hey|hiya|howdy|alright|all right|cheers),? (?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))\\s*[!.,]+\\s+(?P<rest>\\S.*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites44s:_hand_over44s": (
        "b951bbf1e8c4e5d1",
        ((), ("out", "over", "round"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_if_spare44s": ("023424b85db45b64", ((), (" if ",), False), ()),
    "hltl.grounding._rewrites44s:_keep_taking44s": (
        "48aa804d34d0cf7b",
        ((), ("always", "keep"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_keeps_doing44s": ("272204376d1225d5", ((), ("keep",), False), ()),
    "hltl.grounding._rewrites44s:_no_fuss44s": ("12180593b3a8e2c8", ((), ("no ",), False), ()),
    "hltl.grounding._rewrites44s:_opening_remark44s": (
        "a970c5d3b12d51be",
        ((), ("bring", "fetch", "get", "give", "hand", "let", "pass", "send", "take", "th"), True),
        (
            (
                "_OPENING44S",
                (
                    "pattern",
                    "^(?:(?:poor|dear|little|old) )?(?P<who>(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+))(?P<words>(?:'s|\\s)[^.;:!?,]{2,80}?)[,;]\\s*(?:and )?(?:so )?(?:be an? (?:sweetheart|dear|love|star|pal|gem|darling|angel|treasure|good robot) and )?(?P<rest>(?:give|hand|pass|bring|take|get|fetch|let|send)\\b[^.;:!?]*|(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?(?: goes to| go to| is for| are for| is| are|'s|'re) [^.;:!?]*)(?P<end>[.!]?)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites44s:_opening_sorry44s": (
        "9076cbddaf82f573",
        ((), ("sorry",), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_over_they_go44s": ("8130d7575e3a1959", ((), (" go",), False), ()),
    "hltl.grounding._rewrites44s:_past_and44s": ("89227e0fedda724e", ((), (" and ",), False), ()),
    "hltl.grounding._rewrites44s:_run_on_pronoun44s": (
        "020f1a8715f82d6b",
        ((), (" he", " she"), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_shelve44s": ("de34ffbcc74ae6f4", ((), ("shel",), False), ()),
    "hltl.grounding._rewrites44s:_space_on44s": ("1d0dcc67c31ff9d9", ((), ("there",), False), ()),
    "hltl.grounding._rewrites44s:_surface_first44s": (
        "3ee4b5884f343c52",
        ((), (" first",), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_want_so44s": ("43169479d10e7dca", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites44s:_will_do44s": (
        "d0499e7b8d60c4f0",
        (("'ll",), (" will ",), False),
        (),
    ),
    "hltl.grounding._rewrites44s:_without44s": ("8b9cdef304ce43c3", ((), ("without",), False), ()),
    "hltl.grounding._rewrites45:_all_over45": (
        "77589168d3c3d7dd",
        ((), ("all over", "apart"), False),
        (),
    ),
    "hltl.grounding._rewrites45:_back_and45": ("016014c223caa3de", ((), ("from",), False), ()),
    "hltl.grounding._rewrites45:_before_him45": (
        "66163337844836f1",
        ((), ("ahead of when", "before", "till", "until"), True),
        (
            (
                "_BEFORE_HIM45",
                (
                    "pattern",
                    "\\b(?P<head>(?:before|until|till|ahead of when) (?:the|a|an|his|her|their) [a-z]+(?: [a-z]+)? [a-z]+s) (?P<pr>him|her)(?P<end>\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites45:_by_trade45": ("9fd83b832d06dd72", ((), (" by ",), False), ()),
    "hltl.grounding._rewrites45:_eye_on45": ("dfcc24d716d299c2", ((), ("eye",), False), ()),
    "hltl.grounding._rewrites45:_find_first45": (
        "099b8c93859e637c",
        ((), ("dig out", "fetch", "find", "get", "grab", "locate", "track down"), True),
        (
            (
                "_FIND_FIRST45",
                (
                    "pattern",
                    "^(?:please )?(?:find|grab|locate|get|fetch|dig out|track down) (?P<x>(?:the|that|those|these) [a-z]+(?: [a-z]+)?)\\s*[;:.]\\s+(?P<rest>.+)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites45:_i_mean45": ("a641179b91397fcd", ((), ("mean",), False), ()),
    "hltl.grounding._rewrites45:_it_unnamed45": (
        "9cf77fc03144ce4b",
        ((), ("it", "them"), False),
        (),
    ),
    "hltl.grounding._rewrites45:_lacking45": (
        "e9bf3cd99405f8ad",
        ((), ("find", "given", "got", "had", "lost", "mislaid", "out of"), False),
        (),
    ),
    "hltl.grounding._rewrites45:_left_about45": (
        "7450d67ba2a05e94",
        (("forgot",), ("dumped", "left"), False),
        (),
    ),
    "hltl.grounding._rewrites45:_now_she45": ("612983533d94a252", ((), ("now",), False), ()),
    "hltl.grounding._rewrites45:_remark_time45": (
        "43d0c06be042ac2f",
        (
            (),
            (
                "after that",
                "after this",
                "afternoon",
                "afterwards",
                "evening",
                "in a bit",
                "in a while",
                "later",
                "morning",
                "soon",
                "tonight",
            ),
            True,
        ),
        (
            (
                "_REMARK_TIME45",
                (
                    "pattern",
                    "(?P<sep>[.?!]\\s+|,\\s*|;\\s*)(?P<r>(?:he|she|they|i|we)(?:'s|'m|'re| is| am| are| has| have|'ve)? (?:just |then |also )?(?:got|off to|going to|heading to|heading off to|due at|due to|has|have|on|at)\\b[^.?!,;]*?)\\s+(?:later(?: on)?|tonight|after this|after that|afterwards|this (?:afternoon|evening|morning)|in a bit|in a while|soon)(?P<end>\\s*[.?!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites45:_same_as45": ("e24350a5ca045ffd", ((), ("same",), False), ()),
    "hltl.grounding._rewrites45:_they_did45": (
        "31e1a63f435cf7ef",
        ((), ("er", "is"), True),
        (
            (
                "_THEY_DID45",
                (
                    "pattern",
                    "(?P<sep>,\\s*|;\\s*)(?:the|a|an|some|our|my) (?P<who>[a-z]+(?: [a-z]+)?) (?P<v>[a-z]+ed|ate|took|stole|drank|broke|had|nicked|pinched|swiped|scoffed|got|ate up|ran off with|made off with) (?:all (?:of )?|the last of |most of |up )?(?P<pos>his|her) (?P<what>[a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites45:_thing_q45": ("19f0ed30e0235664", (("?",), (), False), ()),
    "hltl.grounding._rewrites45:_what_with45": (
        "3f9115e7506601e7",
        ((), ("what with",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_apiece_tail45r": (
        "ae4982a771cf61c2",
        ((), ("apiece", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_belongs_with45r": (
        "12995a7ac930dc28",
        ((), ("belong", "go with", "goes with"), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_better_verb45r": (
        "c0924aca43c7102c",
        ((), ("best", "better"), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_each_for_folk45r": (
        "bdafba43aa7aebd7",
        ((), ("apiece", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_go_whichever45r": ("295858bde93ee89f", ((), ("way",), False), ()),
    "hltl.grounding._rewrites45r:_isnt_its45r": ("10c6792e2d68df06", ((), ("it",), False), ()),
    "hltl.grounding._rewrites45r:_its_p_doing45r": ("d52d2db6a744cc56", ((), ("it",), False), ()),
    "hltl.grounding._rewrites45r:_leave_it45r": ("348b7d99485a1c06", ((), ("leave",), False), ()),
    "hltl.grounding._rewrites45r:_mind_which45r": ("23545f6b7cf8e4fc", ((), ("which",), False), ()),
    "hltl.grounding._rewrites45r:_no_not45r": ("3b15b283a95e3843", ((), ("no",), False), ()),
    "hltl.grounding._rewrites45r:_one_of_list45r": (
        "93601663784732d0",
        ((), ("one of",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_one_of_them45r": (
        "e28e201d346cdb0d",
        ((), ("one of",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_one_who45r": ("a7d98f626e4df3d3", ((), ("the one",), False), ()),
    "hltl.grounding._rewrites45r:_right_first45r": (
        "9ca736c0740de7a3",
        ((), ("right",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_switch_to45r": (
        "f01a35d6623f981f",
        ((), ("change", "move", "shift", "swap", "switch"), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_the_one45r": ("062f2a3fbdb057f5", ((), ("the one",), False), ()),
    "hltl.grounding._rewrites45r:_wants_to_do45r": (
        "aeeba88fc353bbd4",
        ((), ("wants to",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_what_he_wanted45r": (
        "2daaa7c049eaa511",
        ((), ("it",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_whats_wanted45r": (
        "cf5d202b656f7b66",
        ((), ("'s what",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_which_first45r": (
        "8f11cbc7105d76af",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_which_itches45r": (
        "df86723154321ccc",
        ((), ("which",), False),
        (),
    ),
    "hltl.grounding._rewrites45r:_will_do_one45r": ("0853b4e6ab753a94", ((), ("do",), False), ()),
    "hltl.grounding._rewrites45s:_after_opening45s": (
        "4624e31785c04eef",
        ((), ("after", "following", "since"), True),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites45s:_and_pron45s": ("c9d3fef3907a4108", ((), (" and ",), False), ()),
    "hltl.grounding._rewrites45s:_closer45s": (
        "4f26f629b1d9f6e5",
        ((), ("cheers", "please", "pls", "plz", "ta", "thanks", "thx", "ty"), True),
        (
            (
                "_CLOSER45S",
                ("pattern", "(?<=[a-z]) (?P<c>thx|thanks|ta|cheers|pls|plz|please|ty)\\s*$", 34),
            ),
        ),
    ),
    "hltl.grounding._rewrites45s:_go_too45s": ("09a0cffa9e83c723", ((), (" go to ",), False), ()),
    "hltl.grounding._rewrites45s:_left_it45s": (
        "b1733536b97ad6d7",
        ((), (" it ", " them "), False),
        (),
    ),
    "hltl.grounding._rewrites45s:_run_on45s": (
        "9e6fed30bcfb730f",
        ((), ("he", "it's", "its"), True),
        (
            (
                "_RUN_ON45S",
                (
                    "pattern",
                    "(?<=[a-z]) (?P<p>he|she|hes|shes|he's|she's|its|it's|they|theyre|they're|they've|theyve)(?= [a-z])",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites45s:_so_his45s": ("1d91a1f2ca28498c", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites45s:_state_so45s": ("8ccf72e33ffb7e23", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites45s:_take_to45s": ("7c64360492dce84d", ((), ("take",), False), ()),
    "hltl.grounding._rewrites45s:_they_want45s": ("300c157eaa6844e1", ((), ("they",), False), ()),
    "hltl.grounding._rewrites45s:_who_remark45s": ("a08d3e139959e095", ((), ("who",), False), ()),
    "hltl.grounding._rewrites46:_all_said46": ("871de24093a33822", ((), ("all ",), False), ()),
    "hltl.grounding._rewrites46:_apology46": (
        "3b8f9dead10b2341",
        ((), (" me for ", "excuse me", "forgive me", "hate", "pardon me", "sorry"), True),
        (
            (
                "_APOLOGY_ONLY46",
                (
                    "pattern",
                    "^(?:(?:i'm |i am )?(?:so |very |really |terribly |awfully )?sorry|i hate|hate|forgive me|pardon me|excuse me) (?:to|for) (?:nag|nagging|go on|going on|keep on|keeping on|harp on|harping on|pester you|pestering you|bother you|bothering you|chase|chasing|ask again|asking again|be a (?:pain|pest|nuisance|bore)|being a (?:pain|pest|nuisance|bore))(?: again| about it| you)?\\s*,\\s*(?:only|but)\\s+(?=\\S)|^(?:pardon|excuse|forgive) me(?: for (?:butting in|barging in|cutting in|jumping in|chipping in|breaking in|interrupting|intruding|asking|the interruption|the intrusion|bothering you|nagging))\\s*,\\s*(?:but\\s+)?(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_bare_doing46": (
        "c772da29d0ea234e",
        (("'d ",), (" after ", " since "), False),
        (),
    ),
    "hltl.grounding._rewrites46:_craft46": (
        "50bd3b9abcbdfaa0",
        (
            (),
            (
                "basketry",
                "beadwork",
                "blacksmithing",
                "calligraphy",
                "carpentry",
                "cookery",
                "falconry",
                "fretwork",
                "glassblowing",
                "glasswork",
                "ironwork",
                "joinery",
                "lampwork",
                "leatherwork",
                "marquetry",
                "masonry",
                "metalwork",
                "papermaking",
                "photography",
                "pyrography",
                "quillwork",
                "scrimshaw",
                "silversmithing",
                "stonework",
                "tapestry",
                "taxidermy",
                "upholstery",
                "woodturning",
                "woodwork",
            ),
            True,
        ),
        (
            (
                "_CRAFT46",
                (
                    "pattern",
                    "\\b(?P<a>after|since) (?P<w>basketry|lampwork|woodwork|metalwork|leatherwork|beadwork|fretwork|stonework|ironwork|glasswork|marquetry|joinery|carpentry|falconry|cookery|tapestry|upholstery|masonry|taxidermy|calligraphy|photography|pyrography|scrimshaw|quillwork|papermaking|woodturning|glassblowing|silversmithing|blacksmithing)(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_doing_after46": (
        "445cf2cd8dc2f005",
        ((), ("after", "following", "since"), True),
        (
            (
                "_DOING_AFTER46",
                (
                    "pattern",
                    "^(?P<head>[A-Z][\\w]*(?: [A-Z][\\w]*)?(?:'s| is) [a-z]+ing(?: [a-z]+){0,3}?) (?:after|since|following) (?P<w>[a-z][a-z' ]*?)(?=\\s*(?:,|;| and | so ))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_for_peace46": ("4de7c0e837efb096", ((), ("peace",), False), ()),
    "hltl.grounding._rewrites46:_give_teeth46": ("56c1447b2e8ebeae", ((), (" give ",), False), ()),
    "hltl.grounding._rewrites46:_it_him46": (
        "10465fbd54a582b0",
        ((), ("bring", "fetch", "get", "give", "hand", "pass", "send", "take"), True),
        (
            (
                "_IT_HIM46",
                (
                    "pattern",
                    "\\b(?P<v>give|bring|take|hand|pass|send|fetch|get) (?P<x>it|them) (?=(?:him|her)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_not_for_cleft46": (
        "ff31413e250e7380",
        ((), ("n't for", "not for"), False),
        (),
    ),
    "hltl.grounding._rewrites46:_other_too46": (
        "841bfd09a7ec2fbc",
        ((), ("a bit ", "a touch ", "rather ", "too "), False),
        (),
    ),
    "hltl.grounding._rewrites46:_own_thing46": (
        "63d0d6deafc73b61",
        (
            (),
            (
                "bring",
                "carry",
                "fetch",
                "get",
                "give",
                "hand",
                "pass",
                "pop",
                "run",
                "send",
                "take",
            ),
            True,
        ),
        (
            (
                "_OWN_THING46",
                (
                    "pattern",
                    "\\b(?P<v>give|bring|take|hand|pass|fetch|get|send|carry|run|pop) (?:(?P<pos>his|her) (?P<x>[a-z][a-z ]*?) (?P<part>(?:(?:over|across|back|up|down|round) )?to) (?P<to>him|her)|(?P<to2>him|her) (?P<pos2>his|her) (?P<x2>[a-z][a-z ]*?))(?=\\s*(?:[,.;!?]|$))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_placed_so46": (
        "6de9d9956c934b10",
        ((), (" where ", "can't", "doesn't", "knows", "ready for ", "stops", "won't"), True),
        (
            (
                "_PLACED_SO46",
                (
                    "pattern",
                    "(?P<sep>,?\\s+)(?:so (?:that )?(?P<so>(?-i:[A-Z])[\\w]*(?: (?-i:[A-Z])[\\w]*)?|he|she|they) (?:stops|doesn't|won't|can't|knows)\\b|ready for (?P<owner>(?-i:[A-Z])[\\w]*(?: (?-i:[A-Z])[\\w]*)?)'s [a-z]|(?:next to|near|by|beside) where (?P<near>(?-i:[A-Z])[\\w]*(?: (?-i:[A-Z])[\\w]*)?) )(?P<words>[^,;.!?]*)(?P<end>\\s*[.?!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_so_reason46": ("480ef931c055edaf", ((" so ",), (), False), ()),
    "hltl.grounding._rewrites46:_thanks_ahead46": (
        "d5bcbd5664bc252d",
        ((), ("a lot", "a million", "again", "in advance", "muchly", "so much", "very much"), True),
        (
            (
                "_THANKS_AHEAD46",
                (
                    "pattern",
                    "^(?P<w>[A-Za-z][a-z]+) (?:in advance|so much|very much|ever so much|muchly|again|a lot|a million)\\s*[,:;!]\\s*(?=\\S)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_that_one46": (
        "1c70e705aee795b0",
        ((), (" one",), False),
        (("_THAT_ONE46", ("pattern", "\\b(?:that|this|the other) one\\b", 34)),),
    ),
    "hltl.grounding._rewrites46:_to_purpose46": ("ea6a89b225b19ad4", ((" to ",), (), False), ()),
    "hltl.grounding._rewrites46:_when_done46": (
        "70dfb71411eb4208",
        ((), ("when you",), True),
        (
            (
                "_DONE46",
                (
                    "pattern",
                    "(?P<sep>,?\\s+)when you(?:'re| are) (?:done|through|all done)(?: there| with that| here)?(?P<end>\\s*[.?!]*)\\s*$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46:_would_suit46": (
        "81e0da69225eb9a0",
        ((), (" will ", " would ", "'d ", "'ll "), False),
        (),
    ),
    "hltl.grounding._rewrites46:_you_reckon46": (
        "15df342b7900fb9b",
        ((), ("figure", "imagine", "reckon", "suppose", "think"), True),
        (
            (
                "_YOU_RECKON46",
                (
                    "pattern",
                    "^(?P<o>(?:(?:so|and|oh|well|erm|um),? )*)(?:do|d') ?you (?:reckon|think|suppose|imagine|figure)(?: that)?,? (?P<x>(?!you\\b)[a-z][^,;.?!]*?) (?P<m>could|can|might)\\b(?! (?:have|get|take|use)\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites46r:_a_k_or46r": ("2949d2f27b9631ed", ((), (" or ",), False), ()),
    "hltl.grounding._rewrites46r:_and_both46r": ("d634c2150843e552", ((), ("both",), False), ()),
    "hltl.grounding._rewrites46r:_anything_of46r": (
        "63cb2a46c0049615",
        ((), (" of the ",), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_apiece_first46r": (
        "30e60baaa2ca9dce",
        ((), ("apiece", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_clear_both46r": ("b53180719c8b1a9e", ((), ("alike",), False), ()),
    "hltl.grounding._rewrites46r:_each_pronoun46r": (
        "0c33c5c42ddcdbb4",
        ((), (" each ",), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_fix_why46r": (
        "9fc1d8b6e2eb1d8e",
        ((" are ", " is ", "'re", "'s"), (), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_for_whose46r": ("822e57a69591bb23", (("'s",), (), False), ()),
    "hltl.grounding._rewrites46r:_items_there46r": (
        "8ec345a608b9e684",
        ((), ("here", "see", "there"), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_just_the_one46r": ("64902c27592a178c", ((), ("one",), False), ()),
    "hltl.grounding._rewrites46r:_just_those46r": (
        "97244b9170ebd09a",
        ((), ("just", "only"), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_neither_without46r": (
        "5f0032dc19873c29",
        ((), ("without",), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_not_fussy46r": (
        "56eef7600e434d9c",
        ((), ("fussy", "particular", "picky"), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_one_of_hers46r": (
        "f1c8f5c3ba1c3525",
        ((), (" of her ", " of his "), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_only_one46r": ("1bbf49bc7a655d4a", ((), ("only",), False), ()),
    "hltl.grounding._rewrites46r:_per_head46r": ("2d71fa6cc77640b6", ((), ("out",), False), ()),
    "hltl.grounding._rewrites46r:_placed_remark46r": (
        "8a60364ce1e7d1a2",
        ((), ("ing",), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_scratch_lot46r": (
        "d67317484b861c0f",
        ((), ("scratch",), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_single_thing46r": (
        "71d711bb672bfac1",
        ((), ("thing",), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_slip_label46r": ("812600014359373f", ((), ("who",), False), ()),
    "hltl.grounding._rewrites46r:_taking46r": ("2d9cab64faa00a73", ((), ("taking",), False), ()),
    "hltl.grounding._rewrites46r:_then_again46r": (
        "af268e669930e875",
        ((), ("again", "second", "think"), False),
        (),
    ),
    "hltl.grounding._rewrites46r:_thing_needs46r": ("8a85d1366dab6593", (("'s ",), (), False), ()),
    "hltl.grounding._rewrites46r:_whatever_there46r": (
        "ab60f65395b6d272",
        ((), ("whatever",), False),
        (),
    ),
    "hltl.grounding._rewrites46s:_person_to46s": ("5fbb3dc8d7fb3669", ((" to ",), (), False), ()),
    "hltl.grounding._rewrites47:_all_how47": ("a07ba46a5a0581ed", ((" all ",), (), False), ()),
    "hltl.grounding._rewrites47:_as_trade47": ("883e31796af5ba4d", ((" as ",), (), False), ()),
    "hltl.grounding._rewrites47:_for_doing47": ("2bc98d5d8575a106", (("ing ",), (), False), ()),
    "hltl.grounding._rewrites47:_gloss47": ("1ec197fc82cea51d", ((" for ",), (), False), ()),
    "hltl.grounding._rewrites47:_not_busy47": ("c6a7c6fcf3e0041b", ((), ("if you",), False), ()),
    "hltl.grounding._rewrites47:_owned_occasion47": ("e1c26f798f098faa", (("'s ",), (), False), ()),
    "hltl.grounding._rewrites47:_so_can47": ("47df0011952d2a04", (("so ",), (), False), ()),
    "hltl.grounding._rewrites47:_want_said47": (
        "f3e0c6878db36def",
        ((" need of", " of", " on"), (), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_before_looks47r": (
        "03ad4078a7a96858",
        ((), ("before",), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_claimed47r": ("fb612bbb3ad4861a", ((), ("so ",), False), ()),
    "hltl.grounding._rewrites47r:_clear_of47r": (
        "f9e50f7f493f344f",
        ((), ("clear of",), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_each_given47r": ("235ae55bb770b1be", ((), (" each",), False), ()),
    "hltl.grounding._rewrites47r:_fix_why_goes47r": (
        "dcb4233e3303af93",
        ((), ("to go",), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_heard_but47r": (
        "21d2b4e06106ed49",
        (("corrected", "put me right", "straight"), (), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_mixed_up47r": ("8ab9a5ce4fc26641", ((), ("what",), False), ()),
    "hltl.grounding._rewrites47r:_no_preference47r": (
        "0ef857eb87255dec",
        ((), ("either", "favourite", "preference", "whatever", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_none_there47r": (
        "8d82052ed62a43af",
        ((), ("there ",), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_one_back47r": ("564451df0974c68d", ((), ("the one",), False), ()),
    "hltl.grounding._rewrites47r:_restated47r": ("f328799b1b96503b", ((), ("said",), False), ()),
    "hltl.grounding._rewrites47r:_state_like47r": (
        "e3f6bf9c5dd574b4",
        ((), (" like ",), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_whatever_chooses47r": (
        "6333786773dc573d",
        ((), ("whatever", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites47r:_whichever_of47r": (
        "8e1b516a72d61343",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites47s:_hand_worker47s": ("5dc3b82af252cf36", ((), ("hand",), False), ()),
    "hltl.grounding._rewrites47s:_nobody_else47s": (
        "5531d3f809d732d4",
        ((), (" else",), False),
        (),
    ),
    "hltl.grounding._rewrites47s:_only_after47s": ("842bd3abb5d60922", ((), (" only",), False), ()),
    "hltl.grounding._rewrites47s:_remark_the47s": ("327c8020835dc776", ((), (" the ",), False), ()),
    "hltl.grounding._rewrites47s:_waits47s": ("c2329633ef02e856", ((), ("wait",), False), ()),
    "hltl.grounding._rewrites47s:_whose_answer47s": ("7c0ee316996e512a", (("?",), (), False), ()),
    "hltl.grounding._rewrites48:_apposed48": ("998224eede4a9965", ((), (", a",), False), ()),
    "hltl.grounding._rewrites48:_done_with48": ("fc665aaabffe9b79", ((" with ",), (), False), ()),
    "hltl.grounding._rewrites48:_for_theirs48": ("a2f68135061dae79", ((" for ",), (), False), ()),
    "hltl.grounding._rewrites48:_gloss48": ("0476e943d695a484", ((" say",), (), False), ()),
    "hltl.grounding._rewrites48:_here48": ("b83050d21d041a50", ((" here,",), (), False), ()),
    "hltl.grounding._rewrites48:_hyphened48": (
        "6fb5ddce83492051",
        (("-",), (), False),
        (
            (
                "_WANTED39",
                (
                    "pattern",
                    "\\b(?:wants|needs|fancies|could use|could do with|would love|would like|is after|'s after|could murder|asking for|asked for|been after|on about|(?:is|'s) (?:desperate|gasping|dying|parched|gagging|thirsty|hungry|starving|famished|peckish) for|craving|(?:is|'s) (?:thirsty|hungry|starving|parched|famished|peckish|knackered|shattered|exhausted|worn out))\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites48:_keeps48": ("6bdc1be42f9a61ce", ((" keeps ",), (), False), ()),
    "hltl.grounding._rewrites48:_like48": ("ad3557c7052da99e", ((), ("like,",), False), ()),
    "hltl.grounding._rewrites48:_purpose48": ("cc252e54db0a4098", ((" to ",), (), False), ()),
    "hltl.grounding._rewrites48:_she_is48": ("af65fb7d267035dd", (("He", "She"), (), False), ()),
    "hltl.grounding._rewrites48:_stretch48": ("2fc66d6c0f3e3d0a", ((), ("after a",), False), ()),
    "hltl.grounding._rewrites48:_tag48": ("02fde08ce2f9f3b0", ((" not ", "n't "), (), False), ()),
    "hltl.grounding._rewrites48:_want_said48": (
        "39897a92d27c2075",
        ((), (" eye", " sights", " would "), False),
        (),
    ),
    "hltl.grounding._rewrites48:_while_asked48": (
        "04e9418848f3805b",
        ((" while ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_asking_after_all48r": (
        "3fc03f8f125681eb",
        ((), ("after all",), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_both_want48r": (
        "cbece7e9381cc426",
        ((), ("both", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_each_lead48r": (
        "68a5abddd17c4c6d",
        ((), ("both", "each", "pair", "two of them"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_left_in48r": (
        "a379d763b650c5b6",
        ((), (" left ", " spil"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_not_fussed48r": (
        "b278e2d29116bb7e",
        ((), ("either", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_on_the_line48r": (
        "55e6504c8dfc16e1",
        ((), ("i have", "i've"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_one_of_which48r": (
        "f7d02311b0a30789",
        ((), ("one of the",), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_rather48r": (
        "af06a955a492ecae",
        ((), ("prefer", "rather"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_said_again_for48r": (
        "959e170eb16aa0ce",
        ((), (" for ", " to "), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_scattered48r": (
        "c9c70ab14646e0da",
        ((), ("like", "place", "sea", "sieve"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_take_pick48r": (
        "33672ffdb983f446",
        ((), (" or ", "any", "either", "one of", "whatever", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites48r:_will_do48r": (
        "665626f7357353ab",
        ((), ("'ll do", "will do"), False),
        (),
    ),
    "hltl.grounding._rewrites48s:_can_stay48s": ("9583c4099dc06d21", ((), ("stay",), False), ()),
    "hltl.grounding._rewrites48s:_dislike48s": (
        "7c6059a4fe017662",
        (
            (),
            (
                "abide",
                "allergic",
                "bear",
                "detest",
                "dislike",
                "hate",
                "keen",
                "loathe",
                "stand",
                "stomach",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites48s:_neither48s": ("078ee5deef65a642", ((), ("neither",), False), ()),
    "hltl.grounding._rewrites48s:_not_for_me48s": (
        "0a58f1f2319e4ead",
        ((" for ",), (), False),
        (("_F", ("value", "re.IGNORECASE")), ("re", ("module", "hltl.grounding.gate"))),
    ),
    "hltl.grounding._rewrites49:_after_pastime49": (
        "61e68ef484e074be",
        (("fter ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_asking_after49": (
        "7cf2c6ad6d0f4649",
        (("asking after ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_asks_whether49": (
        "8cedccaeebb74f5c",
        ((" ask", " wonder"), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_could_use49": ("968ea3207f9a6671", ((" after ",), (), False), ()),
    "hltl.grounding._rewrites49:_for_that49": (
        "7dca3751c1c746e4",
        (("for that", "for the job", "for this"), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_grateful49": ("0f28823000f238b5", (("grateful",), (), False), ()),
    "hltl.grounding._rewrites49:_had_nothing49": (
        "4aa7d01922a0b01a",
        (("had nothing",), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_having49": ("b3a2446dfdd0356d", (("having ",), (), False), ()),
    "hltl.grounding._rewrites49:_heart_set49": (
        "2ed72bec2620f55e",
        (("heart set on",), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_hinting49": (
        "242eaa4435f88adf",
        (("banging on", "going on about", "hinting ", "hints about"), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_in_way49": ("346d99fa7f34acad", ((" way",), (), False), ()),
    "hltl.grounding._rewrites49:_last_of49": (
        "03f553ec4a64075f",
        (
            ("few of the ", "half of the ", "last of the ", "remainder of the ", "rest of the "),
            (),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites49:_left49": ("e237dab75b148fe3", ((" left ",), (), False), ()),
    "hltl.grounding._rewrites49:_midway49": (
        "94bd2ab25158e3d2",
        (("Half way ", "Halfway ", "Midway ", "Part way ", "Partway "), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_minutes49": ("77480460f9291440", (("minute",), (), False), ()),
    "hltl.grounding._rewrites49:_objection49": (
        "c4033bf12f4dcad5",
        ((), ("any objection to ",), False),
        (),
    ),
    "hltl.grounding._rewrites49:_one_thing49": ("7674ab59f1f9c7ef", ((), ("thing",), False), ()),
    "hltl.grounding._rewrites49:_pass_time49": (
        "fd4a79a619f74865",
        (("fill the", "kill ", "pass the", "while away"), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_poor49": ("1ad173e6cfc307f0", ((), ("poor ",), False), ()),
    "hltl.grounding._rewrites49:_seeing49": ("c16b7e70f18f8087", ((", seeing ",), (), False), ()),
    "hltl.grounding._rewrites49:_skipped49": (
        "6e568fa9b6442813",
        ((" gave up ", " missed ", " skipped ", " went without "), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_sort_out49": ("856d17f34611b4be", (("sorting ",), (), False), ()),
    "hltl.grounding._rewrites49:_thanks_from49": ("3993a0e8e1fc4819", (("With ",), (), False), ()),
    "hltl.grounding._rewrites49:_theirs49": (
        "e3f9ef7fc4bf312a",
        ((" hers", " his"), (), False),
        (),
    ),
    "hltl.grounding._rewrites49:_up_from49": ("dab0b54a55558906", ((" up from ",), (), False), ()),
    "hltl.grounding._rewrites49:_what_wants49": ("00503af6f74833ad", ((" what ",), (), False), ()),
    "hltl.grounding._rewrites49:_while_want49": ("c26c0e98789804df", (("while ",), (), False), ()),
    "hltl.grounding._rewrites49r:_both_taking49r": ("ca071c6020a4ed13", ((), ("both",), False), ()),
    "hltl.grounding._rewrites49r:_both_there_are49r": (
        "2f4d4cac755385fc",
        ((), ("both",), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_care_which49r": ("999caa5a072bd9a6", ((), ("care",), False), ()),
    "hltl.grounding._rewrites49r:_cleft49r": (
        "f395951aa5944c10",
        ((), (" for ", "it is ", "it was ", "it's "), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_each_of_the49r": (
        "6811f9689d2ee761",
        ((), ("each of the",), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_fussy_about49r": ("867e42554abfbda0", ((), (" or ",), False), ()),
    "hltl.grounding._rewrites49r:_not_that49r": (
        "2e7f800ff236b1fd",
        ((), ("not that ,", "not that,"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_of_the_two49r": (
        "6c2b33caa6f2f3e3",
        ((), (" of the pair", " of the two"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_one_to_get49r": (
        "f01481e31fec032c",
        ((), ("one", "single"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_only_thing49r": ("44b80d7248ff4349", ((), ("only",), False), ()),
    "hltl.grounding._rewrites49r:_pair_of49r": ("78c8bd39c9630e0d", ((), ("pair of",), False), ()),
    "hltl.grounding._rewrites49r:_says_wants49r": (
        "2315cdeb88475731",
        ((), (" said ", " told ", "mentioned"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_seeing_as_one49r": (
        "479f2fc2f7bad1c6",
        ((), ("there",), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_something_for49r": ("979f1ee47210bc60", ((":",), (), False), ()),
    "hltl.grounding._rewrites49r:_surface_for49r": (
        "091455818cd04812",
        ((), (" for ",), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_wants_out49r": (
        "0dd6d9607d810ab9",
        ((), (" out", "hand", "ready"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_whatever_of49r": (
        "f0f536ed2657408c",
        ((), ("any one", "anything", "whatever", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites49r:_with_one49r": ("6d2e4481064ead86", ((), ("with ",), False), ()),
    "hltl.grounding._rewrites49s:_cleft_reach49s": ("90aa24b73c4f7eb4", ((), ("not",), False), ()),
    "hltl.grounding._rewrites49s:_dont_go49s": ("46908ad10649e173", ((), (" go ",), False), ()),
    "hltl.grounding._rewrites49s:_go_on49s": (
        "9909a2feb9ac8858",
        ((), ("come on", "go on"), False),
        (),
    ),
    "hltl.grounding._rewrites49s:_isnt_either49s": (
        "eaf9953e12b496c2",
        (("n't",), (" not ",), False),
        (),
    ),
    "hltl.grounding._rewrites49s:_keep_waiting49s": (
        "3f2ff4da900843f1",
        ((), ("hanging", "waiting"), False),
        (),
    ),
    "hltl.grounding._rewrites49s:_let_at49s": ("13ccbb654140b7be", ((), (" at ",), False), ()),
    "hltl.grounding._rewrites49s:_no_point49s": (
        "04383ea20229bb5a",
        ((), ("it's no", "no ", "there", "theres"), False),
        (),
    ),
    "hltl.grounding._rewrites49s:_not_touched49s": ("488d728976d22c16", ((), (" be ",), False), ()),
    "hltl.grounding._rewrites49s:_on_top49s": ("8ac719cf54db2c4e", ((), ("on top",), False), ()),
    "hltl.grounding._rewrites49s:_own_other49s": (
        "25b744e29ce281e5",
        ((), (" own ", "else"), False),
        (),
    ),
    "hltl.grounding._rewrites49s:_so_run_on49s": ("256a6d769f64e3b9", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites49s:_theres_minute49s": (
        "14a7bea7b43d813d",
        ((), ("there",), False),
        (),
    ),
    "hltl.grounding._rewrites50:_finding50": (
        "d842f06fd9a45f3b",
        (("its way", "their way"), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_first_week50": (
        "9a3dadf6b9dc4eff",
        (("first ", "last ", "second "), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_gloss50": ("0483ece445a1381b", ((" in ", " on "), (), False), ()),
    "hltl.grounding._rewrites50:_hands_on50": (
        "63b54d9868be1137",
        ((" hands on ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_long_day50": ("fa44db200bdc908a", (("After ",), (), False), ()),
    "hltl.grounding._rewrites50:_making50": ("c033a1fafec6053b", (("ing ",), (), False), ()),
    "hltl.grounding._rewrites50:_no_rush50": ("9a1ff02c9d0c2811", (("and no ",), (), False), ()),
    "hltl.grounding._rewrites50:_nothing_since50": (
        "0eb4f5c6c946bb45",
        (("nothing",), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_ok_with_you50": (
        "7520dbb981e3d947",
        ((" with you to ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_old_one50": (
        "190e72e1410bf422",
        ((" last ", " old ", " own ", "usual"), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_only50": ("89ec4e06a3d5f599", ((", only ",), (), False), ()),
    "hltl.grounding._rewrites50:_only_one50": (
        "79f07751b2bdcf7e",
        (("being the only one",), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_out_of_way50": ("bd957e96085c4815", ((" way",), (), False), ()),
    "hltl.grounding._rewrites50:_pleases50": ("da01f4ea43390e21", ((), ("it pleas",), False), ()),
    "hltl.grounding._rewrites50:_reaching50": ("1614e7274cdc6fe7", ((" for ",), (), False), ()),
    "hltl.grounding._rewrites50:_reckons50": ("66edaf027b94236a", ((" as ",), (), False), ()),
    "hltl.grounding._rewrites50:_respect50": ("e984542edfd9e2a6", (("With ",), (), False), ()),
    "hltl.grounding._rewrites50:_span50": ("43718c20d4cd46ca", (("after ",), (), False), ()),
    "hltl.grounding._rewrites50:_thank_you50": ("7b4d47ef19bd2c13", (("thank",), (), False), ()),
    "hltl.grounding._rewrites50:_thing_need50": (
        "f68f7baace25c87d",
        ((" in need of ", " in want of "), (), False),
        (),
    ),
    "hltl.grounding._rewrites50:_to_take50": ("15d1935c782749f7", (("to take ",), (), False), ()),
    "hltl.grounding._rewrites50:_what_after50": ("2f81c6c34b97ffb2", ((" what ",), (), False), ()),
    "hltl.grounding._rewrites50r:_both_the_and50r": (
        "b75772a6dba8c20c",
        ((), ("both",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_for_role50r": (
        "e0edfd1392cb68fc",
        ((), ("for the ",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_instead_why50r": (
        "d8b8c8d0c9f7dc0b",
        ((), ("instead",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_lay_hands50r": (
        "6a70b673886cca21",
        ((), (" you can ",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_lone_in50r": (
        "10871012adb662de",
        ((), ("lone", "only", "single", "sole"), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_lot_of_them50r": (
        "56ca8c882142b974",
        ((), ("of 'em", "of them"), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_not_bothered_which50r": (
        "48db1f347fc622e9",
        ((), ("which",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_one_of_and50r": (
        "85a2237f1796fe28",
        ((), (" of the ",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_one_there50r": ("f233b9b9af07432b", ((), ("there",), False), ()),
    "hltl.grounding._rewrites50r:_pair_wants50r": (
        "0175ccbb298c129c",
        ((), (" need", " want"), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_play_with50r": (
        "4be3a172bb946843",
        ((), ("any", "either", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_role_says50r": ("8bcf82c9da6188d8", ((), (", the ",), False), ()),
    "hltl.grounding._rewrites50r:_said_why50r": (
        "840daa386732b038",
        (("wanted",), (" asked ", " said "), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_says_both50r": ("478cd834fb36f87e", ((), ("both",), False), ()),
    "hltl.grounding._rewrites50r:_so_to50r": ("69da5cb58cc3db8f", ((), (", so ",), False), ()),
    "hltl.grounding._rewrites50r:_where_it_lives50r": (
        "a1cf4daaf4e0ef8f",
        ((), ("where ",), False),
        (),
    ),
    "hltl.grounding._rewrites50r:_will_do_for50r": (
        "c3cba2fb8ddbadf1",
        ((), (" do ", " do,"), False),
        (),
    ),
    "hltl.grounding._rewrites50s:_cold_on50s": (
        "2b7de269cb62c3c7",
        ((), (" the ",), True),
        (
            (
                "_COLD_ON50S",
                (
                    "pattern",
                    "(?P<cold>[,;.]\\s*(?:and |cos |because )?it(?:'s| is| gets)(?: (?:so|really|very|bitter|perishing|freezing))? (?:cold|freezing|chilly|nippy|parky|bitter|perishing|hot|boiling|baking|roasting|warm|damp|draughty|drafty))(?P<place> (?:on|by|at|near|in|over) the [a-z]+(?: [a-z]+)?)(?P<end>\\s*[.!]?\\s*)$",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites50s:_head_over50s": (
        "0b7c8028064a3a67",
        ((), ("can", "could", "might", "will", "would"), True),
        (
            (
                "_HEAD_OVER50S",
                (
                    "pattern",
                    "^(?P<lead>\\s*(?:could|can|would|will|might) (?P<x>(?:the|that|those|these) [a-z]+(?: [a-z]+)??) )(?:head|wander|trot|toddle|travel|drift|hop|nip|pop)(?= (?:over |across |along |round )?to\\b)",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites50s:_no_no_just50s": ("44a93db1cca36bbf", ((), ("no ",), False), ()),
    "hltl.grounding._rewrites50s:_not_again50s": ("e2e2a53b562be6fa", ((), ("not",), False), ()),
    "hltl.grounding._rewrites50s:_not_cleft50s": (
        "941979dbab2e886b",
        ((), ("n't", "never", "not"), False),
        (),
    ),
    "hltl.grounding._rewrites50s:_now_over50s": ("2bdfd44c18eac56a", ((), ("now",), False), ()),
    "hltl.grounding._rewrites50s:_on_way50s": ("4cc9488c7b43e608", ((), (" way",), False), ()),
    "hltl.grounding._rewrites50s:_purpose_when50s": (
        "245f07b6d8fa8f07",
        ((), ("for ",), False),
        (),
    ),
    "hltl.grounding._rewrites50s:_so_not_that50s": (
        "5537dc6b908ea5db",
        ((), ("so not",), False),
        (),
    ),
    "hltl.grounding._rewrites51:_a_mates51": ("5ba6df920f585b26", (("'s ",), (), False), ()),
    "hltl.grounding._rewrites51:_after_state51": ("c409b0c12222ba21", (("After ",), (), False), ()),
    "hltl.grounding._rewrites51:_all_after51": ("2242a042e3a1208e", (("all ",), (), False), ()),
    "hltl.grounding._rewrites51:_at_the51": ("9f03e34f87cf6c68", (("At ",), (), False), ()),
    "hltl.grounding._rewrites51:_been51": ("65749fd6ddc30338", (("'s been ",), (), False), ()),
    "hltl.grounding._rewrites51:_been_needing51": (
        "90eed2c89e247ec6",
        (("been needing",), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_being_a51": ("256438f2ef8ab41d", (("being a",), (), False), ()),
    "hltl.grounding._rewrites51:_both_on51": ("415d29cdc3d60338", ((" both ",), (), False), ()),
    "hltl.grounding._rewrites51:_bottle_of51": ("bacc235f4e341dfe", ((" of ",), (), False), ()),
    "hltl.grounding._rewrites51:_clear51": (
        "900bc41370d5da3c",
        ((" clean", " clear", " empty", " free", " tidy"), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_do_you_think51": (
        "e7e7891de26d6548",
        (("D'you ", "Do ", "Would "), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_ever_since51": (
        "6f0b1fe9ea88aafd",
        (("Ever ", "Since ", "since "), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_favour51": ("3b1df734663ed8e6", ((" as a ",), (), False), ()),
    "hltl.grounding._rewrites51:_flagging51": ("69cc2a81fe68b0cb", ((" after ",), (), False), ()),
    "hltl.grounding._rewrites51:_gloss51": ("81f166b1a096aba7", ((" you",), (), False), ()),
    "hltl.grounding._rewrites51:_grab_it51": ("1ad48a5a207c156e", ((" so ",), (), False), ()),
    "hltl.grounding._rewrites51:_i_mean51": ("268ce7a1f87a2f5a", (("I mean",), (), False), ()),
    "hltl.grounding._rewrites51:_its_ones51": ("ec33553f2486866f", (("It",), (), False), ()),
    "hltl.grounding._rewrites51:_lend_ours51": ("73c00daf748b2e4b", (("ours",), (), False), ()),
    "hltl.grounding._rewrites51:_nothing_fancier51": (
        "b62169374e656f34",
        (("nothing ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_outsider51": (
        "c08435593a5151c6",
        ((" asked ", " is ", " needs ", " wants "), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_over_with51": (
        "947555cb7950e004",
        ((" over with ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_pair51": (
        "902d7b1c05a11a49",
        ((" of them", "the pair", "the two"), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_proper51": ("903bd6cfdb3eecae", ((" for ",), (), False), ()),
    "hltl.grounding._rewrites51:_same_as51": ("9ffb2836c126996d", (("same as ",), (), False), ()),
    "hltl.grounding._rewrites51:_short_a51": ("e1db282ecc961caa", ((" short ",), (), False), ()),
    "hltl.grounding._rewrites51:_since_clause51": (
        "7530a5af3341630a",
        ((" since ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_spare51": (
        "15775c65e7957eb6",
        (("free", "quiet", "spare"), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_star51": ("2c236c45140aa1be", (("f you",), (), False), ()),
    "hltl.grounding._rewrites51:_thanks_in51": (
        "00c994f5e3faa1c3",
        ((" ta", "cheers", "thank"), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_the_lass51": (
        "1661fb32c66beebf",
        ((" that", " who"), (), False),
        (),
    ),
    "hltl.grounding._rewrites51:_with_apologies51": (
        "0a432fdce66c937c",
        (("With ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_all_there_is51r": (
        "0e50f6065ec9d3aa",
        ((), (" all ", " only "), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_any_one_on51r": (
        "fdc3e32b5e2a6cbf",
        ((), ("matter which",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_asked_one_of51r": (
        "98dced6d9f1eecc8",
        ((), ("of th",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_both_comma51r": (
        "d5aee992c33a7387",
        ((), ("both ,", "both,"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_both_of_them51r": (
        "34c317a97bf1d149",
        ((), ("both of them",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_clearing51r": (
        "bf338d6d05533be2",
        ((), ("clean", "clear", "empty", "sort", "tidy", "tidying", "wip"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_each_have51r": (
        "be929e99d1e06328",
        ((), ("apiece", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_earned51r": (
        "98ff14b2ff219dff",
        ((), ("deserved", "earned"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_front_choice51r": (
        "2c75c30018eec1da",
        ((), ("any", "either", "whichever"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_had_enough51r": (
        "05c8fdc6ce28556f",
        ((), ("enough", "fed up", "fill", "had it", "tired"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_its_the_asked51r": (
        "10148d79c2c35c40",
        ((), ("it is the", "it was the", "it's the"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_kept_on51r": (
        "538fd3d9b2401399",
        ((), (" it ", " them "), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_left_a51r": (
        "ce2e220207b6b261",
        ((), (" out", "left"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_likes_both51r": (
        "847a0570a7090ae1",
        ((), (" both", "deserv", "earned", "either"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_listed51r": ("7cb20ea7ae508459", ((":",), (), False), ()),
    "hltl.grounding._rewrites51r:_nobody_sulks51r": (
        "dc591f11f5bf98be",
        ((), ("no one", "no-one", "nobody", "of them"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_not_a51r": (
        "a3c95dd1d43e2b62",
        ((), ("not a", "not the"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_one_in_here51r": (
        "83758f39bfe18a1f",
        ((), ("lone ", "one ", "only ", "single ", "sole "), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_one_with51r": (
        "387ba14c4a5ec950",
        ((), ("the one ",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_only_one51r": ("6faf60749df0fd57", ((), (" one",), False), ()),
    "hltl.grounding._rewrites51r:_pick_of51r": ("c51c95cacdc68fae", ((), ("pick of",), False), ()),
    "hltl.grounding._rewrites51r:_she_said_make51r": (
        "86f372ca79200f35",
        ((), ("change", "make"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_so_long_as51r": (
        "6d17110d70711009",
        ((), ("long as", "provid"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_taking_to51r": ("0a7fcd4c70a8b5b3", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites51r:_the_one_is51r": (
        "bcf044dbef4a1458",
        ((), ("the one",), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_they_share51r": (
        "ee251b65a40b22f9",
        ((), ("both", "halves", "share", "split", "swap"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_too_warm51r": ("c78140c5837947a1", ((), ("too ",), False), ()),
    "hltl.grounding._rewrites51r:_why_fix51r": (
        "6bdb190ab50e43f4",
        ((",",), (), False),
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
    "hltl.grounding._rewrites51r:_would_suit51r": (
        "6f08f7bd82c555c9",
        ((), ("content", "please", "satisf", "suit"), False),
        (),
    ),
    "hltl.grounding._rewrites51r:_yes_again51r": (
        "33f987015a2bb99a",
        ((), ("aye", "correct", "right", "yeah", "yep", "yes"), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_and_not_person51s": (
        "751dbd84360d9cb1",
        ((), (" not ",), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_being_a51s": ("da97a909dc016cd7", ((), ("being",), False), ()),
    "hltl.grounding._rewrites51s:_dont_bother51s": (
        "9dc0b1ce7b42a133",
        ((), ("bother",), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_hold_back51s": ("154aeb1e8a236eeb", ((), ("from",), False), ()),
    "hltl.grounding._rewrites51s:_itll_why51s": (
        "d1bb3b6a3442d426",
        ((), (" will ", "'ll"), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_ll_will51s": ("55c966da75da871f", ((), ("'ll",), False), ()),
    "hltl.grounding._rewrites51s:_not_wanted_when51s": (
        "048c2e30d37dcbed",
        ((), ("n't", "never", "not"), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_nothing_but51s": (
        "b057e81b7d402d89",
        ((), ("nothing",), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_only_cleft51s": ("6c3a85f852460b3a", ((), ("only",), False), ()),
    "hltl.grounding._rewrites51s:_pair_can51s": ("8ae54d3bfe209c60", ((), (" of ",), False), ()),
    "hltl.grounding._rewrites51s:_reason_instead51s": (
        "d1fe8a99fad044d1",
        ((), ("instead",), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_sort_those51s": ("f56e6f7887b3e13c", ((), ("sort",), False), ()),
    "hltl.grounding._rewrites51s:_where_after51s": (
        "770f3b24aeba6abf",
        ((", ",), (), False),
        (("re", ("module", "hltl.grounding.gate")),),
    ),
    "hltl.grounding._rewrites51s:_which_stays51s": (
        "e77c649c20e0b05b",
        ((), ("that", "which"), False),
        (),
    ),
    "hltl.grounding._rewrites51s:_who_run_on51s": ("b04dd69c52314806", ((), (" who",), False), ()),
    "hltl.grounding._rewrites52:_after_care52": (
        "dbce148ce7c024ca",
        (("after", "following"), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_asking_if52": (
        "e97c2104f2f387f7",
        ((" if ", "whether"), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_before_ps52": ("3ca3a67ccc6fa559", (("'s ",), (), False), ()),
    "hltl.grounding._rewrites52:_butting_in52": ("c72b5049c08ed370", ((" in",), (), False), ()),
    "hltl.grounding._rewrites52:_cataphor52": ("cb0ac932ec2c2c11", ((), ("he", "she"), False), ()),
    "hltl.grounding._rewrites52:_clearing52": ("164b7f5bc62b73cb", (("ing the ",), (), False), ()),
    "hltl.grounding._rewrites52:_colleague52": ("f80bcd5dc7563330", ((", ",), (), False), ()),
    "hltl.grounding._rewrites52:_do_for52": ("3af8637b1d2c5d12", ((" do ",), (), False), ()),
    "hltl.grounding._rewrites52:_doing_next52": ("a8290b6c0884aa7b", ((" so ",), (), False), ()),
    "hltl.grounding._rewrites52:_hands_full52": ("60c5b4a7f3ddc6cd", ((" hands ",), (), False), ()),
    "hltl.grounding._rewrites52:_hanging_about52": (
        "b30bdd241089d40a",
        ((" for ",), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_high_and_low52": ("02ef338b8e87f7f4", ((" for ",), (), False), ()),
    "hltl.grounding._rewrites52:_lot_in52": (
        "f2789974a02899b0",
        ((" are ", " is ", "'re ", "lot"), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_my_hands52": (
        "5515167bfb149400",
        (("busy", "eyes", "hands", "snowed"), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_no_pressure52": ("257f2cbf7d073bf3", ((" but",), (), False), ()),
    "hltl.grounding._rewrites52:_off_your_hands52": (
        "a5e4fb49349e01c8",
        ((" hands",), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_ready_on52": (
        "aa2c1ab378288215",
        (("laid out", "ready", "set out"), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_sat_on52": (
        "af591b1148fffe2c",
        ((" at ", " by ", " in ", " on "), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_short_of52": ("f4fd8c5e311ba795", (("short of",), (), False), ()),
    "hltl.grounding._rewrites52:_since_event52": ("fa525dafa4af6574", (("since ",), (), False), ()),
    "hltl.grounding._rewrites52:_starts_in52": ("9de7fecaecc7c549", ((" in ",), (), False), ()),
    "hltl.grounding._rewrites52:_teeny52": ("45ffed5f3ba67f39", (("one ",), (), False), ()),
    "hltl.grounding._rewrites52:_to_do_his52": ("67e1ba89dcb2ada0", ((" to ",), (), False), ()),
    "hltl.grounding._rewrites52:_to_look52": ("c4533d4353cc8ca0", ((" to ",), (), False), ()),
    "hltl.grounding._rewrites52:_whatsoever52": ("51a4d50ca5bf4e15", (("no ",), (), False), ()),
    "hltl.grounding._rewrites52:_when_done52": (
        "e69f0039d0464de4",
        (("done", "finished", "sorted"), (), False),
        (),
    ),
    "hltl.grounding._rewrites52:_whereas52": ("1f5732624a016b6c", (("whereas",), (), False), ()),
    "hltl.grounding._rewrites52:_would_let52": ("f5c016d73c079281", (("let ",), (), False), ()),
    "hltl.grounding._rewrites52r:_away_in52r": (
        "35f6e73d72fa12fa",
        ((), (" it ", " them "), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_both_off52r": (
        "29d5228b1a495993",
        ((), ("both of them",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_both_state52r": (
        "448fd6028a2f735e",
        ((), (" both ",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_each_kind52r": (
        "a4905ee152663586",
        ((), ("apiece", "both", "each", "every"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_every_one52r": ("4c4aa1767f0c31ea", ((), ("every",), False), ()),
    "hltl.grounding._rewrites52r:_filler_fix52r": (
        "e58aa42a7d5fff8f",
        ((), (",",), False),
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
    "hltl.grounding._rewrites52r:_give_each52r": (
        "c908ec7ec0f0bcfe",
        ((), ("both", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_grab_first52r": ("ee26dffef6ddd62c", ((), ("first",), False), ()),
    "hltl.grounding._rewrites52r:_in_the_end52r": (
        "a767520e76b8ad8a",
        ((), (" end", "eventually", "said and done"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_knocking52r": (
        "2ee220ac1b9a5cf9",
        ((), ("about", "around"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_left_out52r": (
        "87dd742be7816868",
        ((), ("left out",), False),
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
    "hltl.grounding._rewrites52r:_meant_mine52r": (
        "f12162f350fec4c4",
        ((), ("i mean",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_meant_to_say52r": (
        "802b1312a46678d5",
        ((), ("mean to", "meant"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_needs_the52r": (
        "ecd6b81ad03bd270",
        ((), ("booked the", "need the", "needs the", "using the", "wants the"), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_one_bag52r": ("0b27225616730642", ((), ("the one",), False), ()),
    "hltl.grounding._rewrites52r:_one_of_them52r": (
        "1e663cff1be73411",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_only_one52r": ("cc95abafc064772c", ((), (" to ",), False), ()),
    "hltl.grounding._rewrites52r:_pair_of52r": ("d7bbe086cd608917", ((), ("things",), False), ()),
    "hltl.grounding._rewrites52r:_said_fix52r": ("a013fe209af1bd4e", ((), (" not ",), False), ()),
    "hltl.grounding._rewrites52r:_single_which52r": (
        "60fce3654ccabddb",
        ((), ("which",), False),
        (),
    ),
    "hltl.grounding._rewrites52r:_vague_to52r": ("f688d687fcb6f5a8", ((), (",",), False), ()),
    "hltl.grounding._rewrites52r:_who_asked52r": (
        "f2d2f8127d1b7d6a",
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
    "hltl.grounding._rewrites52r:_whole_lot52r": (
        "6c00918ff2fae2cd",
        (
            (),
            ("bundle", "chuck", "collect", "gather", "lot of", "round up", "scoop", "sweep", "tip"),
            True,
        ),
        (
            (
                "_SWEEP52R",
                (
                    "pattern",
                    "^(?P<v>sweep|scoop|gather|bundle|tip|chuck|round up|collect) (?=(?:up )?(?:all |both |the ))",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites52s:_after_all52s": (
        "fc5bbc0cce5890a0",
        ((), ("after all",), False),
        (),
    ),
    "hltl.grounding._rewrites52s:_dont_just52s": (
        "ebd7cfe29f993d4d",
        ((), ("just", "only"), False),
        (),
    ),
    "hltl.grounding._rewrites52s:_not_use52s": (
        "ce8a679b5a784da6",
        ((), ("drink", "eat", "use"), False),
        (),
    ),
    "hltl.grounding._rewrites53:_about_it53": ("73552e9bb11c1b4e", (("about it",), (), False), ()),
    "hltl.grounding._rewrites53:_as_for53": (
        "eca030a362956160",
        (("s for ", "s regards ", "s to "), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_ask_me53": (
        "7ea818b420c3e640",
        (("ask me", "my money", "opinion", "two pennies", "you and me"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_between53": (
        "80e870e09697fd1e",
        ((" both", " of them", " pair", " two"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_cleft53": (
        "94a5497bed56572b",
        (("one ", "thing "), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_clutter53": ("2c0a39389077d31c", (("ing ",), (), False), ()),
    "hltl.grounding._rewrites53:_dibs53": (
        "1963833dc0e2891a",
        ((" on it", " on them", "dibs on"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_doing_and53": ("3a0fe8a03a4a625f", (("ing ",), (), False), ()),
    "hltl.grounding._rewrites53:_over_there53": ("64d231a9fb56b140", ((" over ",), (), False), ()),
    "hltl.grounding._rewrites53:_pron_after53": (
        "872a6445d7671d3e",
        ((" is after ", "s after "), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_ramble53": ("d273c8785c15f782", ((" but",), (), False), ()),
    "hltl.grounding._rewrites53:_since_ended53": ("34c6afbe25711e92", (("since ",), (), False), ()),
    "hltl.grounding._rewrites53:_stack_of53": ("fb0744a70e8d9d84", ((" of ",), (), False), ()),
    "hltl.grounding._rewrites53:_swing_by53": ("49da1bc59b9cf83c", ((" with ",), (), False), ()),
    "hltl.grounding._rewrites53:_thanks_two53": (
        "e4531f3e1558a826",
        ((" a lot", " a million", " again", " in advance", " much"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_throat53": (
        "280ae5ee840e4fa9",
        (("mouth", "throat"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53:_wants_there53": ("16aadea2541aa45b", ((" there",), (), False), ()),
    "hltl.grounding._rewrites53:_whenever53": (
        "f4c9e832ed220f6f",
        ((" ur ", " yr ", "henever", "youre"), (), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_as_well_as53r": (
        "d97a5524da8e3444",
        ((), (" plus ", "along with", "as well as", "together with"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_both_of_them53r": (
        "3179d54477598bc7",
        ((), ("of them",), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_can_drink53r": ("37d585c2f949fad1", ((), ("things",), False), ()),
    "hltl.grounding._rewrites53r:_each_get53r": ("04001f23ec208740", ((), ("each",), False), ()),
    "hltl.grounding._rewrites53r:_either_hand53r": ("f8dafeb204e7f064", ((), ("hand",), False), ()),
    "hltl.grounding._rewrites53r:_fix_for53r": ("39c9bd61980ceb2a", ((), (" for ",), False), ()),
    "hltl.grounding._rewrites53r:_goes_there53r": (
        "f97bb202ada32333",
        ((), (" it", "there"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_had_lot53r": ("68040d4cb8603d61", ((), (" and ",), False), ()),
    "hltl.grounding._rewrites53r:_its_actually53r": (
        "06b9e8e772f9cb47",
        ((), ("actually", "in fact", "really"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_need_more53r": ("5ba82c77ecce98de", ((), ("one",), False), ()),
    "hltl.grounding._rewrites53r:_not_first53r": ("0d72ae05f3321c59", ((), ("not ",), False), ()),
    "hltl.grounding._rewrites53r:_on_offer53r": ("a8d4c4a4b0fb802f", ((), ("thing",), False), ()),
    "hltl.grounding._rewrites53r:_one_who_is53r": (
        "ea45265c0c404401",
        ((), ("the one",), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_particular53r": (
        "7d405b1a17dd5020",
        ((), ("about which", "which"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_per_person53r": (
        "2db07e135c93b09b",
        ((), (" per ", ":"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_rethink53r": (
        "42877feb45fe394e",
        ((), ("plan", "reflection", "scratch that", "second thought", "think"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_route53r": (
        "990d9d43966c51fe",
        ((), (" up ", " way ", "however", "path", "route"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_said_before53r": (
        "21414d497e7313f9",
        ((), (" asked ", " said ", " told ", "wrote"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_says_any53r": (
        "10a302d87b10df26",
        ((), ("reckons", "said", "says", "tells me"), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_whichever_of53r": (
        "a591128f0706e739",
        ((), ("whichever of",), False),
        (),
    ),
    "hltl.grounding._rewrites53r:_will_suit53r": (
        "4271cc6db4847655",
        ((), (" do ", " good", " ok", "alright", "fine", "keep", "please", "suit"), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_all_for53s": (
        "2c8ccb564b79b3fc",
        ((), (" by ", " for ", " near ", "alongside", "beside", "next to"), False),
        (
            (
                "_BESIDE_WORDS53S",
                ("patterns", "strings", ("beside", "next to", "alongside", " by ", " near ")),
            ),
        ),
    ),
    "hltl.grounding._rewrites53s:_claimed53s": (
        "fde067c9c348c94f",
        (
            (),
            (
                "chosen",
                "hand up",
                "hands up",
                "name down",
                "name for",
                "name on",
                "names down",
                "names for",
                "names on",
                "opted",
                "picked",
                "plumped",
            ),
            False,
        ),
        (
            (
                "_CLAIM_WORDS53S",
                (
                    "patterns",
                    "strings",
                    (
                        "hand up",
                        "hands up",
                        "name on",
                        "name down",
                        "name for",
                        "names on",
                        "names down",
                        "names for",
                        "picked",
                        "chosen",
                        "opted",
                        "plumped",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites53s:_dont_down53s": ("b06986c731172647", ((), ("down",), False), ()),
    "hltl.grounding._rewrites53s:_every_single53s": (
        "edb5ad9d36019eaf",
        ((), ("every", "which"), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_goes_to53s": (
        "7a50c8a55411c6cb",
        ((), ("go both", "go th", "goes both", "goes th"), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_its_for53s": (
        "ae57d41e0f835bdb",
        (
            (),
            (
                " now",
                "at all",
                "ate",
                "done",
                "earlier",
                "eating",
                "eats",
                "finished",
                "got",
                "had",
                "has it",
                "have it",
                "it",
                "it is",
                "it's",
                "last night",
                "taken",
                "they are",
                "they're",
                "took",
                "yesterday",
            ),
            True,
        ),
        (
            (
                "_UNSAFE53S",
                (
                    "pattern",
                    "\\b(?:had|got|has it|have it|eating|eaten|ate|eats|took|taken|finished|yesterday|earlier|last night|(?:it's|it is|they're|they are) (?:his|hers|theirs|all (?:his|hers))|(?:his|hers|theirs) now|(?:he|she|they)(?:'s| has| have|'ve) (?:got|had)|done)\\b",
                    34,
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites53s:_much_rather53s": (
        "fd60e75ecc535939",
        ((), ("rather",), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_nobody_else53s": (
        "9706828ac829a2e0",
        ((), (" else",), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_not_who53s": (
        "03061a9c3c025af9",
        ((), ("the one", "who is", "who's"), False),
        (),
    ),
    "hltl.grounding._rewrites53s:_to_with53s": ("7c2927715b4a1946", ((), (" with th",), False), ()),
    "hltl.grounding._rewrites54:_after_doing54": (
        "c996c1fbf026a0b8",
        ((), (" after ",), False),
        (),
    ),
    "hltl.grounding._rewrites54:_after_had54": (
        "1d01440e2cd13b45",
        ((), ("done with", "finished", "had ", "used "), False),
        (),
    ),
    "hltl.grounding._rewrites54:_before_gets54": (
        "cefdc6cba8984c97",
        (
            (),
            (
                "before any",
                "before it",
                "before some",
                "before that",
                "before they",
                "before those",
            ),
            False,
        ),
        (),
    ),
    "hltl.grounding._rewrites54:_cant_get_up54": (
        "15596a96d50e6ff7",
        ((), ("can not", "can't", "cannot", "cant", "couldn't"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_craving54": (
        "36463622024fb79f",
        (
            (),
            (" yen ", "craving", "fancy", "hankering", "heart", "hunger", "longing", "thirst"),
            False,
        ),
        (
            (
                "_CRAVING_WORDS54",
                (
                    "patterns",
                    "strings",
                    (
                        "craving",
                        "hankering",
                        " yen ",
                        "longing",
                        "hunger",
                        "thirst",
                        "fancy",
                        "heart",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites54:_for_time54": ("ed2864590a211873", ((), (" time",), False), ()),
    "hltl.grounding._rewrites54:_go_by54": (
        "c10e593a1932c5c4",
        ((), ("as you", "when you"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_grand54": (
        "3800e83ba953391f",
        (
            (),
            (
                "brill",
                "business",
                "champion",
                "cracking",
                "dandy",
                "grand",
                "just the job",
                "magic",
                "marvel",
                "smashing",
                "splendid",
                "spot on",
                "terrific",
                "tremendous",
            ),
            False,
        ),
        (
            (
                "_GRAND_WORDS54",
                (
                    "patterns",
                    "strings",
                    (
                        "grand",
                        "smashing",
                        "champion",
                        "marvel",
                        "splendid",
                        "cracking",
                        "magic",
                        "brill",
                        "terrific",
                        "tremendous",
                        "business",
                        "just the job",
                        "spot on",
                        "dandy",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites54:_minute_ago54": (
        "9ea2d99ade18a432",
        ((), (" ago", "just now"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_nothing_to54": (
        "b04856b879052972",
        ((), ("nothing for", "nothing to"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_only_one54": ("19fef7c520de9fab", ((), ("?",), False), ()),
    "hltl.grounding._rewrites54:_over_goes54": (
        "950591888644300a",
        (
            (),
            ("it goes", "one goes", "that goes", "these go", "they go", "this goes", "those go"),
            False,
        ),
        (
            (
                "_OVER_WORDS54",
                (
                    "patterns",
                    "strings",
                    (
                        "it goes",
                        "they go",
                        "that goes",
                        "those go",
                        "these go",
                        "this goes",
                        "one goes",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites54:_possible54": (
        "9529e19e9c427866",
        ((), (" ok ", " okay ", "all right", "alright", "possible"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_run54": ("e8526eddae042a50", ((), ("running",), False), ()),
    "hltl.grounding._rewrites54:_suit54": (
        "d1c39786bfeb2bb0",
        ((), ("would do", "would suit"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_thai54": ("5c91981fa0aa3b8d", ((), ("khun", "sawa"), False), ()),
    "hltl.grounding._rewrites54:_them_over54": (
        "eed74faca250e2f4",
        ((), ("them across", "them over", "them round"), False),
        (),
    ),
    "hltl.grounding._rewrites54:_where_cant54": ("897791b073ccc4be", ((), ("where ",), False), ()),
    "hltl.grounding._rewrites54r:_alike54r": ("c758157dfc2f40cd", ((), (" alike",), False), ()),
    "hltl.grounding._rewrites54r:_all_asking54r": (
        "767134ae31780ab0",
        ((), (" is all ",), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_at_her54r": (
        "6426e673b36b7ccf",
        ((), (" at her ", " at his ", " at their "), False),
        (("_says54r", ("function", "hltl.grounding._rewrites54r:_says54r", "38a603163a1d9b8e")),),
    ),
    "hltl.grounding._rewrites54r:_at_the_time54r": (
        "474f8af1c13ced35",
        ((), (" at th", " then"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_cue_idiom54r": (
        "6506688a15496033",
        ((), ("cross that", "fire", "horses", "rub that", "wipe that"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_direction54r": (
        "4c2205e962d3c6b7",
        ((), ("direction",), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_do_her54r": ("f8b461f19df74207", ((), ("will do",), False), ()),
    "hltl.grounding._rewrites54r:_either_person54r": (
        "f8266374555cb358",
        ((), ("either", "one or the other"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_fussy_about54r": (
        "e254c44c58f539bf",
        ((), (" about ",), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_having_lot54r": (
        "0ed1487bd58c5c77",
        ((), ("all of them", "everything", "the lot", "them all"), False),
        (("_says54r", ("function", "hltl.grounding._rewrites54r:_says54r", "38a603163a1d9b8e")),),
    ),
    "hltl.grounding._rewrites54r:_he_fancied54r": (
        "7c6d786ff13a37df",
        ((), ("it is", "it was", "it's"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_he_said54r": (
        "21789cb5d8b435a2",
        ((), ("he asked", "he meant", "he said", "he says", "he told", "he wanted"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_however54r": (
        "2062c990c22c9cfb",
        ((), ("however", "way"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_likes_to54r": (
        "41fa6742fd9b5326",
        ((), ("enjoy", "like to", "likes to", "love to", "loves to"), False),
        (("_says54r", ("function", "hltl.grounding._rewrites54r:_says54r", "38a603163a1d9b8e")),),
    ),
    "hltl.grounding._rewrites54r:_lone54r": (
        "9c21a3fe08e6239c",
        ((), ("lone", "sole ", "solitary"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_mind_which54r": (
        "59667a2f27ae6573",
        ((), (" which ",), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_no_more54r": (
        "fa6c99d0ede40546",
        ((), ("hunt", "look", "search"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_one_going54r": (
        "a6395a30cf9304ef",
        ((), ("the one",), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_only_one54r": (
        "684f3cb9f92d8430",
        ((), ("only a single thing", "only one thing", "only the one thing"), False),
        (("_says54r", ("function", "hltl.grounding._rewrites54r:_says54r", "38a603163a1d9b8e")),),
    ),
    "hltl.grounding._rewrites54r:_owed54r": ("77c36b563e8d616c", ((), (":",), False), ()),
    "hltl.grounding._rewrites54r:_stacked54r": (
        "625f4994cbb31f36",
        ((), ("of them,", "piled", "placed", "stacked", "stood", "the pair"), False),
        (("_says54r", ("function", "hltl.grounding._rewrites54r:_says54r", "38a603163a1d9b8e")),),
    ),
    "hltl.grounding._rewrites54r:_the_pair54r": (
        "2d4f470419d4908f",
        ((), ("the both", "the pair", "the two", "twosome"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_to_have54r": (
        "5b108d7bb88c2de7",
        ((), (" to hang on", " to have", " to keep", " to take home"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_wanted_by54r": (
        "53cffbe467ab0250",
        ((), ("asked for by", "needed by", "requested by", "wanted by"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_we_have54r": (
        "d1dff9456a7f2391",
        ((), ("there are", "there is", "we"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_where_reach54r": (
        "72bdb233935242f4",
        ((), (" where ",), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_who_now54r": (
        "a40b1f5a40efd636",
        ((), (" one", "i mean", "mixed", "muddled", "wrong"), False),
        (),
    ),
    "hltl.grounding._rewrites54r:_yes_to_her54r": (
        "f19c61d895b11e6d",
        ((), ("aye", "right", "yeah", "yep", "yes"), False),
        (),
    ),
    "hltl.grounding._rewrites54s:_doing_with54s": ("7aaea4826e8b2740", (("ing ",), (), False), ()),
    "hltl.grounding._rewrites54s:_no_point54s": (
        "400137e5c39cdcfc",
        ((), ("'s ", "no "), False),
        (),
    ),
    "hltl.grounding._rewrites54s:_no_then_want54s": ("3f274e46c48d3727", ((), ("no",), False), ()),
    "hltl.grounding._rewrites54s:_none_for54s": ("665382099e951461", ((), ("no",), False), ()),
    "hltl.grounding._rewrites54s:_not_that54s": (
        "8f30c9f6fa8cb978",
        ((), ("that", "who"), False),
        (),
    ),
    "hltl.grounding._rewrites54s:_not_today54s": (
        "175bb9c138e8edc3",
        ((), ("n't", "not"), False),
        (),
    ),
    "hltl.grounding._rewrites54s:_nothing_again54s": (
        "acda2d9f19850e02",
        ((), ("nothing",), False),
        (),
    ),
    "hltl.grounding._rewrites54s:_stays_cleft54s": (
        "5bb6bf4c6788d9b0",
        ((), ("it is", "it's"), False),
        (),
    ),
    "hltl.grounding._rewrites54s:_where_twice54s": (
        "f74f848f4abf9bcb",
        ((), ("down ", "over there", "up "), False),
        (),
    ),
    "hltl.grounding._rewrites55:_away55": (
        "8054a0e1debad3da",
        ((), ("away from", "clear of", "reach of", "sight of"), False),
        (
            (
                "_AWAY_WORDS55",
                ("patterns", "strings", ("away from", "reach of", "sight of", "clear of")),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_bless55": (
        "e7931fc2eb8998c9",
        (
            (),
            (
                "for bearing with",
                "for being patient",
                "for being so patient",
                "for being very patient",
                "for hanging on",
                "for holding on",
                "for waiting",
                "for your patience",
            ),
            False,
        ),
        (
            (
                "_BLESS_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "for waiting",
                        "for your patience",
                        "for being patient",
                        "for being so patient",
                        "for being very patient",
                        "for holding on",
                        "for hanging on",
                        "for bearing with",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_drink_from55": (
        "1de6a8aaa3f82b42",
        ((), ("drink", "glass", "refill", "sip", "splash", "swig", "top-up"), False),
        (
            (
                "_DRINK_WORDS55",
                (
                    "patterns",
                    "strings",
                    ("drink", "glass", "sip", "swig", "splash", "top-up", "refill"),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_favour55": (
        "0c7ba333a35e4547",
        ((), ("favor", "favour"), False),
        (),
    ),
    "hltl.grounding._rewrites55:_gem55": (
        "4cbf5d4f3380dff6",
        (
            (),
            ("if you be", "if you could be", "if you will be", "if you would be", "if you'd be"),
            False,
        ),
        (
            (
                "_GEM_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "if you'd be",
                        "if you would be",
                        "if you could be",
                        "if you will be",
                        "if you be",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_heart55": ("d1c3655df5a6224a", ((), ("set on",), False), ()),
    "hltl.grounding._rewrites55:_interrupt55": (
        "71895d8f6c79b019",
        (
            (),
            (
                "to barge in",
                "to bother you",
                "to butt in",
                "to cut in",
                "to disturb you",
                "to interrupt",
                "to intrude",
                "to pester you",
                "to trouble you",
            ),
            False,
        ),
        (
            (
                "_INTERRUPT_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "to interrupt",
                        "to butt in",
                        "to barge in",
                        "to cut in",
                        "to bother you",
                        "to trouble you",
                        "to disturb you",
                        "to pester you",
                        "to intrude",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_irish55": ("4fcb9a2f40a7e80b", ((), ("raibh",), False), ()),
    "hltl.grounding._rewrites55:_mix55": ("959df2c8ab09d0bc", ((), ("mix",), False), ()),
    "hltl.grounding._rewrites55:_moment55": (
        "d04f1bac776ab5cc",
        ((), ("at present", "the moment", "this moment"), False),
        (),
    ),
    "hltl.grounding._rewrites55:_on_at55": (
        "b61b4e522124cf34",
        ((), ("on at me", "on at us"), False),
        (),
    ),
    "hltl.grounding._rewrites55:_passing55": (
        "9f31cc31b66ad961",
        (
            (),
            (
                "you are going by",
                "you are going past",
                "you are passing",
                "you are walking past",
                "you're going by",
                "you're going past",
                "you're passing",
                "you're walking past",
            ),
            False,
        ),
        (
            (
                "_PASSING_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "you're passing",
                        "you're going past",
                        "you're walking past",
                        "you're going by",
                        "you are passing",
                        "you are going past",
                        "you are walking past",
                        "you are going by",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_porfa55": ("89ec838c1a59a341", ((), ("porf",), False), ()),
    "hltl.grounding._rewrites55:_pretty55": (
        "a08cb8d20adf196f",
        ((), ("pretty please",), False),
        (),
    ),
    "hltl.grounding._rewrites55:_purpose55": (
        "047ac7a274ddf153",
        ((), (" for ", " to "), False),
        (),
    ),
    "hltl.grounding._rewrites55:_reach55": (
        "d8f12be642ca7928",
        ((), ("can find", "can get", "can grab", "can reach", "can see"), False),
        (
            (
                "_REACH_WORDS55",
                (
                    "patterns",
                    "strings",
                    ("can reach", "can get", "can grab", "can see", "can find"),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_runon55": (
        "74d227102670d943",
        (
            (),
            (
                " bring it",
                " bring them",
                " fetch it",
                " fetch them",
                " give it",
                " give them",
                " hand it",
                " hand them",
                " pass it",
                " pass them",
                " send it",
                " send them",
                " take it",
                " take them",
            ),
            False,
        ),
        (
            (
                "_RUNON_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        " pass it",
                        " pass them",
                        " give it",
                        " give them",
                        " hand it",
                        " hand them",
                        " bring it",
                        " bring them",
                        " take it",
                        " take them",
                        " fetch it",
                        " fetch them",
                        " send it",
                        " send them",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_runon_remark55": (
        "39a0088c6d537707",
        (
            (),
            (
                " he is ",
                " he's ",
                " hes ",
                " she is ",
                " she's ",
                " shes ",
                " they're ",
                " theyre ",
            ),
            False,
        ),
        (
            (
                "_REMARK_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        " hes ",
                        " shes ",
                        " he's ",
                        " she's ",
                        " he is ",
                        " she is ",
                        " theyre ",
                        " they're ",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_sec55": (
        "eea9b6cc3a2657fc",
        (
            (),
            ("a chance", "a jiffy", "a min", "a minute", "a mo", "a sec", "a spare", "a tick"),
            False,
        ),
        (
            (
                "_SEC_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "a sec",
                        "a minute",
                        "a min",
                        "a mo",
                        "a tick",
                        "a jiffy",
                        "a chance",
                        "a spare",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_specific55": (
        "43f11ae5d9e2e340",
        (
            (),
            ("especially", "exactly", "mind you", "particular", "precisely", "specifically"),
            False,
        ),
        (
            (
                "_SPECIFIC_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "specifically",
                        "particular",
                        "precisely",
                        "especially",
                        "exactly",
                        "mind you",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_that_is55": (
        "1f0ab0aa6f8b86f3",
        ((), ("that is", "that's who"), False),
        (),
    ),
    "hltl.grounding._rewrites55:_then_after55": ("0e3721bd88c23c2d", ((), ("then",), False), ()),
    "hltl.grounding._rewrites55:_there55": (
        "05245da057e096db",
        (
            (),
            ("behind there", "down there", "in there", "inside there", "under there", "up there"),
            False,
        ),
        (
            (
                "_THERE_WORDS55",
                (
                    "patterns",
                    "strings",
                    (
                        "under there",
                        "down there",
                        "in there",
                        "up there",
                        "inside there",
                        "behind there",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites55:_while55": (
        "3f1c26942c3ee9bf",
        ((), ("been ",), False),
        (("_WHILE_WORDS55", ("patterns", "strings", ("while", "ages", "long time"))),),
    ),
    "hltl.grounding._rewrites55r:_any_fine55r": (
        "2a476575de93a93f",
        ((), (" fine", " ok", "good", "grand", "right"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_apiece55r": (
        "73e97ae8c1e93dfc",
        ((), ("apiece", "each"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_carrying55r": ("156ae0739876f567", ((), ("so ",), False), ()),
    "hltl.grounding._rewrites55r:_chance_youd55r": (
        "7f5f654ee7f2cd94",
        ((), ("you'd",), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_closer_to_hand55r": (
        "bdba4cf37d9f1b66",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_come_to55r": ("ddf43c7477aed397", ((), (" come",), False), ()),
    "hltl.grounding._rewrites55r:_every_alike55r": (
        "0cab9cec86391d2b",
        ((), ("alike",), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_fit_in55r": (
        "fd1c582666caf3d0",
        ((), ("fit in", "manage", "squeeze in", "time for"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_goes_on55r": ("73c00083a484368c", ((), ("that go",), False), ()),
    "hltl.grounding._rewrites55r:_grab_nearest55r": (
        "a84f2d09d0d0562f",
        ((), ("closer", "closest", "easiest", "handiest", "nearer", "nearest"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_in_they_go55r": (
        "dfb0c61b42b24abe",
        ((), ("it goes", "they go"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_my_error55r": ("5453a671ee1208ec", ((), ("my ",), False), ()),
    "hltl.grounding._rewrites55r:_no_such55r": (
        "f60fb993fb86d1d3",
        ((), ("there is no ", "there's no "), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_not_word55r": ("20fc4e54bd115323", ((), (", not ",), False), ()),
    "hltl.grounding._rewrites55r:_on_s_go55r": ("d598779370d79f5c", ((), (" go ",), False), ()),
    "hltl.grounding._rewrites55r:_one_of_two55r": (
        "659d9b13646438e0",
        ((), ("either", "one of"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_only_one55r": (
        "0af4a18491e0c464",
        ((), ("the only",), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_out_to55r": ("a7ed428136c44350", ((), (" out to ",), False), ()),
    "hltl.grounding._rewrites55r:_passing_asked55r": (
        "2fd66bf827f0df31",
        ((), ("going by", "passing", "past"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_spare_minute55r": (
        "81af274326405bc9",
        ((), (" mo ", "jiffy", "minute", "moment", "sec", "tick"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_spoken_for55r": (
        "ef23a3f93da121a1",
        ((), ("bagged", "called for", "reserved", "spoken for"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_surface_for55r": (
        "eef75b800a42979f",
        ((), (" for the ",), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_those_n55r": ("b6224cada48b3c70", ((":",), (), False), ()),
    "hltl.grounding._rewrites55r:_twin55r": ("ed1aa673902b0866", ((), (" its ",), False), ()),
    "hltl.grounding._rewrites55r:_um_yes55r": (
        "28cfdf67d1fd8853",
        ((), ("for,", "to,"), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_was_it55r": ("9a02cc8c427d513d", ((), ("was it ",), False), ()),
    "hltl.grounding._rewrites55r:_with_them55r": (
        "3d024c5a35b6a73f",
        ((), (" so ", " with "), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_wouldnt_mind55r": (
        "b1d1bde518e57303",
        ((), ("mind",), False),
        (),
    ),
    "hltl.grounding._rewrites55r:_wrap_in55r": ("f8edf4b6edc6cf99", ((), ("wrap ",), False), ()),
    "hltl.grounding._rewrites55s:_bare_adj55s": (
        "049e7ddda279c0d3",
        ((), ("instead", "n't ", "no ", "not ", "rather"), False),
        (("_SET_ASIDE55S", ("patterns", "strings", ("not ", "n't ", "instead", "rather", "no "))),),
    ),
    "hltl.grounding._rewrites55s:_cant_have55s": (
        "c1054a7570e2acd0",
        ((), ("can", "n't", "not"), False),
        (),
    ),
    "hltl.grounding._rewrites55s:_its_wanting55s": (
        "1c56930d6805f899",
        ((), ("after", "needing", "wait ", "wanting"), False),
        (),
    ),
    "hltl.grounding._rewrites55s:_no_one_but55s": ("027ec351ce1a59de", ((), ("no",), False), ()),
    "hltl.grounding._rewrites55s:_not_theirs55s": (
        "33a6913802e3baf7",
        ((), ("n't", "not"), False),
        (),
    ),
    "hltl.grounding._rewrites55s:_scrap_for55s": (
        "6882ea602bf78d73",
        (
            (),
            ("cross off", "ditch", "drop", "forget", "never mind", "scrap", "skip", "strike off"),
            False,
        ),
        (
            (
                "_SCRAP55S",
                (
                    "patterns",
                    "strings",
                    (
                        "scrap",
                        "skip",
                        "forget",
                        "ditch",
                        "drop",
                        "never mind",
                        "cross off",
                        "strike off",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites56:_again56": ("e5def21c32f6119a", ((), ("me again",), False), ()),
    "hltl.grounding._rewrites56:_are_his56": (
        "ee3a9d5dbcce2168",
        ((), (" hers,", " his,"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_body_so56": (
        "8575a4c82c5a7637",
        ((), (" so he ", " so she ", " so they "), False),
        (),
    ),
    "hltl.grounding._rewrites56:_both_people56": ("8850758b6c813b6b", ((), (" both",), False), ()),
    "hltl.grounding._rewrites56:_chuffed56": (
        "9288a1cb6f92b5fd",
        (
            (),
            (
                "chuffed",
                "delighted",
                "ecstatic",
                "made up",
                "over the moon",
                "stoked",
                "thrilled",
                "tickled",
            ),
            False,
        ),
        (
            (
                "_CHUFFED_WORDS56",
                (
                    "patterns",
                    "strings",
                    (
                        "chuffed",
                        "delighted",
                        "thrilled",
                        "made up",
                        "over the moon",
                        "tickled",
                        "stoked",
                        "ecstatic",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites56:_faff56": ("ce58a097d524188e", ((), ("too much",), False), ()),
    "hltl.grounding._rewrites56:_favour_after56": (
        "03df16875d17f053",
        ((), ("favor", "favour"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_finds56": ("ce169fc9dcf76cbc", ((), ("find", "found"), False), ()),
    "hltl.grounding._rewrites56:_for_and56": ("e689e0fa57ac512e", ((), (" for ",), False), ()),
    "hltl.grounding._rewrites56:_gap56": (
        "de1a60c3f5b5427c",
        ((), (" after ", " for "), False),
        (),
    ),
    "hltl.grounding._rewrites56:_go_on56": (
        "79ecb41e1d86732b",
        ((), ("come on", "go on"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_harms56": ("b393d94be84e6fac", ((), ("harms way",), False), ()),
    "hltl.grounding._rewrites56:_has_none56": ("b73bd23b42ee5b3c", ((), (" no ",), False), ()),
    "hltl.grounding._rewrites56:_ing_things56": (
        "0075f7a742e61cf6",
        ((), ("ing and that", "ing bits", "ing stuff", "ing things", "ing with"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_keeps_so56": ("5252c3ffda2edcc6", ((), (" so ",), False), ()),
    "hltl.grounding._rewrites56:_kindness56": (
        "b107f4ec324f3e1a",
        ((), ("do me a", "do us a"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_lost_without56": (
        "023a46129108a4f5",
        ((), ("lost without",), False),
        (),
    ),
    "hltl.grounding._rewrites56:_name_q56": ("5549bc4bfe70f563", (("?",), (), False), ()),
    "hltl.grounding._rewrites56:_oclock56": (
        "55912376a0a8188d",
        (
            (),
            (
                "0 am",
                "0am",
                "1 am",
                "1am",
                "2 am",
                "2am",
                "3 am",
                "3am",
                "4 am",
                "4am",
                "5 am",
                "5am",
                "6 am",
                "6am",
                "7 am",
                "7am",
                "8 am",
                "8am",
                "9 am",
                "9am",
                "clock",
                "pm",
            ),
            False,
        ),
        (
            (
                "_OCLOCK_WORDS56",
                (
                    "patterns",
                    "strings",
                    (
                        "clock",
                        "pm",
                        "0am",
                        "1am",
                        "2am",
                        "3am",
                        "4am",
                        "5am",
                        "6am",
                        "7am",
                        "8am",
                        "9am",
                        "0 am",
                        "1 am",
                        "2 am",
                        "3 am",
                        "4 am",
                        "5 am",
                        "6 am",
                        "7 am",
                        "8 am",
                        "9 am",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites56:_owner_so56": ("518316221ee8cbc4", ((), ("'s,", "’s,"), False), ()),
    "hltl.grounding._rewrites56:_paid56": (
        "753dfc3dd3b91b75",
        ((), ("bought", "chose", "ordered", "paid for", "picked"), False),
        (
            (
                "_PAID_WORDS56",
                ("patterns", "strings", ("paid for", "bought", "ordered", "chose", "picked")),
            ),
        ),
    ),
    "hltl.grounding._rewrites56:_reason_it56": ("5ba45ecf168755d1", ((), (" it",), False), ()),
    "hltl.grounding._rewrites56:_reckons56": (
        "4c1c24bfb2abcf60",
        (
            (),
            ("go down a treat", "go down nicely", "go down well", "hit the spot", "just the"),
            False,
        ),
        (
            (
                "_RECKONS_WORDS56",
                (
                    "patterns",
                    "strings",
                    (
                        "hit the spot",
                        "go down a treat",
                        "go down well",
                        "go down nicely",
                        "just the",
                    ),
                ),
            ),
        ),
    ),
    "hltl.grounding._rewrites56:_run_over56": (
        "b58aa951aa48ac80",
        ((), (" you ",), False),
        (("_RUN_OVER_WORDS56", ("patterns", "strings", (" over", " across", " round"))),),
    ),
    "hltl.grounding._rewrites56:_shes_got56": ("b83095aac5dc62e7", ((), (" got ",), False), ()),
    "hltl.grounding._rewrites56:_stir56": (
        "658285e1ce42f588",
        ((), (" hers", " his", " theirs"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_suits56": (
        "4d1ca5ce91552c80",
        ((), ("convenient", "suits"), False),
        (),
    ),
    "hltl.grounding._rewrites56:_surface_for56": (
        "ce3ed71ec577025d",
        ((), (" for the ",), False),
        (),
    ),
    "hltl.grounding._rewrites56:_the_one56": ("cc968019773636f8", ((), ("the one ",), False), ()),
    "hltl.grounding._rewrites56:_then_onto56": ("7af0b70c4c448b4a", ((), (", then ",), False), ()),
    "hltl.grounding._rewrites56:_to_look56": ("f61b25ed1f7a5e9a", ((), (" to ",), False), ()),
    "hltl.grounding._rewrites56:_with_it56": (
        "fcfa9ec45dfb8ed8",
        ((), (" with it", " with them"), False),
        (
            (
                "_WITH_IT_WORDS56",
                ("patterns", "strings", ("over to", "across to", "round to", "along to")),
            ),
        ),
    ),
    "hltl.grounding._rewrites56r:_any_spare56r": ("9792d81d896c95ae", ((), ("spare",), False), ()),
    "hltl.grounding._rewrites56r:_as_well_as56r": (
        "c09e0c20f27f3f29",
        ((), ("as well as",), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_backwards56r": (
        "fdbfec0a301f6e49",
        ((), ("swap", "switch"), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_belong_with56r": (
        "96c3a34a49fdd53a",
        ((), (" go ", "belong"), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_both_are_his56r": (
        "7a4ba524b4e44bfd",
        ((), ("both",), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_both_off_to56r": ("58fd839e72b13a31", ((), ("both",), False), ()),
    "hltl.grounding._rewrites56r:_both_want_go56r": (
        "1e68c09ae88fec8c",
        ((), (" of them", "both"), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_doing_so56r": ("f5a36b8b4f692858", ((), (", so ",), False), ()),
    "hltl.grounding._rewrites56r:_every_last56r": ("31b30606ce6e18ea", ((), ("every",), False), ()),
    "hltl.grounding._rewrites56r:_goes_there56r": ("a0835ee372fd35a6", ((), ("there",), False), ()),
    "hltl.grounding._rewrites56r:_gone_walkabout56r": (
        "c5dca43c5ea6a797",
        ((), ("hers", "his", "their"), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_helps_self56r": ("2a9c52968ab5bc7d", ((), ("help",), False), ()),
    "hltl.grounding._rewrites56r:_in_they_go56r": (
        "e1b3c41dbb0c91d4",
        ((), ("it goes", "they go"), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_lay_hand56r": ("ba469155adc0742d", ((), ("hand",), False), ()),
    "hltl.grounding._rewrites56r:_make_that_for56r": (
        "61d434f84e996bc9",
        ((), ("make ",), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_mind_which56r": (
        "18eb296057ff1d1b",
        ((), ("mind which",), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_of_the_n56r": ("fbda01c89287ecc4", ((), ("of the",), False), ()),
    "hltl.grounding._rewrites56r:_on_list56r": ("bba6f28762639ef1", ((), ("list",), False), ()),
    "hltl.grounding._rewrites56r:_only_single56r": (
        "6ca351adc3978dfd",
        ((), ("just", "only"), False),
        (),
    ),
    "hltl.grounding._rewrites56r:_pair_of56r": ("3efb8f4707bf55a3", ((), ("pair of",), False), ()),
    "hltl.grounding._rewrites56r:_whichever_of56r": (
        "fbb9b4b6a916b049",
        ((), ("whichever",), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_anyone_but56s": (
        "17557f431d80dbbb",
        ((), ("any", "some"), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_leave_alone56s": (
        "ca8d466bd9cac78d",
        ((), ("leave ",), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_left_out56s": (
        "e14b7fb98156fb14",
        ((), (" out", "let "), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_no_interest56s": (
        "0e8c2b0876861829",
        ((), ("interest",), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_not_for_take56s": (
        "ebf6d433da75bdbc",
        ((), ("for ",), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_nothing_else56s": (
        "4aa594d7cf029085",
        ((), (" else",), False),
        (),
    ),
    "hltl.grounding._rewrites56s:_off_the56s": ("29d16ba13a224a43", ((), (" off ",), False), ()),
    "hltl.grounding.normalise:_people_then_pronoun": (
        "b9a19a7f46080ecd",
        ((), (",",), True),
        (("_rx", ("function", "hltl.grounding._normalise1:_rx", "c45b8b30fae68122")),),
    ),
    "hltl.grounding.normalise:_while_there36s": (
        "ce30883fd4e256c0",
        ((), ("while you",), True),
        (
            (
                "_WHILE_THERE36S",
                (
                    "pattern",
                    "(?P<lead>^|,)\\s*while (?:you're|you are) (?:there|over there|passing|up there)\\s*,\\s*",
                    34,
                ),
            ),
        ),
    ),
}
