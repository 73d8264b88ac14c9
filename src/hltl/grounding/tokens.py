"""Tokens one LLM grounding query costs, counted offline as GPT-4o-mini would count them."""

from __future__ import annotations

import json

from hltl.errors import GroundingError
from hltl.grounding.offline import OfflineGrounder
from hltl.grounding.prompt import build_messages
from hltl.spec.printer import to_string
from hltl.world.scene import Scene


def estimate_grounding_tokens(instruction: str, scene: Scene) -> int:
    """Tokens GPT-4o-mini would count for grounding ``instruction`` with hltl's LLM prompt.

    The prompt is exactly what :class:`hltl.grounding.llm.LLMGrounder` sends (the rules, the
    few-shot examples chosen for the instruction, the scene and the instruction); the completion
    is the answer that the offline grounder's spec corresponds to, in the answer format. An update
    ("Also give …") is counted as the LLM grounder sends it: the new part alone. Counted with the
    o200k vocabulary of ``bpe-openai`` (the ``llm`` extra); 0 when it is not installed or the
    offline grounder cannot read the instruction.
    """
    try:
        import bpe_openai
    except ImportError:
        return 0
    text = instruction
    for lead in ("Also ", "also "):
        if text.startswith(lead):
            text = text[len(lead) :]
            text = text[:1].upper() + text[1:]
    try:
        g = OfflineGrounder().ground(text, scene)
    except GroundingError:
        return 0
    answer = {
        "root": g.spec.root,
        "formulas": [{"name": n, "formula": to_string(f)} for n, f in g.spec.formulas],
        "entities": list(g.entities),
        "error": None,
    }
    enc = bpe_openai.get_encoding("o200k_base")
    # 3 tokens of chat framing per message and 3 to prime the reply, as OpenAI counts them
    prompt = sum(3 + len(enc.encode(m["content"])) for m in build_messages(text, scene)) + 3
    return prompt + len(enc.encode(json.dumps(answer)))
