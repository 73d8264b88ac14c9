"""Tiny random-weight transformers models (OWLv2, SAM 2, CLIP) written to a local directory the
way a user's downloaded weights would be: config, safetensors, processor and a tokenizer made
here (byte-level, no merges). They test the open-vocabulary plumbing, never accuracy."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

transformers: Any = pytest.importorskip("transformers")
torch: Any = pytest.importorskip("torch")

WIDTH = 32  # hidden size of every tiny tower
IMAGE = 64  # CLIP / OWLv2 input side (4 × 4 patches of 16)
SAM_SIDE = 128  # SAM 2 input side (mask logits at 32 × 32)
BOS, EOS = 512, 513  # after the 2 × 256 byte tokens


def tokenizer() -> Any:
    """A CLIP tokenizer over single bytes (each with and without CLIP's end-of-word mark)."""
    from tokenizers import pre_tokenizers

    vocab: dict[str, int] = {}
    for c in sorted(pre_tokenizers.ByteLevel.alphabet()):
        vocab.setdefault(c, len(vocab))
        vocab.setdefault(c + "</w>", len(vocab))
    # the special tokens last, as in CLIP's own vocabulary: OWL takes a query whose first token
    # has id 0 for padding
    vocab["<|startoftext|>"] = BOS
    vocab["<|endoftext|>"] = EOS
    return transformers.CLIPTokenizer(vocab=vocab, merges=[])


def _towers(vocab_size: int) -> tuple[dict[str, Any], dict[str, Any]]:
    text = {
        "vocab_size": vocab_size,
        "hidden_size": WIDTH,
        "intermediate_size": 2 * WIDTH,
        "num_hidden_layers": 1,
        "num_attention_heads": 2,
        "max_position_embeddings": 32,
        "bos_token_id": BOS,
        "eos_token_id": EOS,
        "pad_token_id": EOS,
    }
    vision = {
        "hidden_size": WIDTH,
        "intermediate_size": 2 * WIDTH,
        "num_hidden_layers": 1,
        "num_attention_heads": 2,
        "image_size": IMAGE,
        "patch_size": 16,
    }
    return text, vision


def save_clip(path: Path, seed: int = 0) -> Path:
    tok = tokenizer()
    text, vision = _towers(len(tok))
    torch.manual_seed(seed)
    model = transformers.CLIPModel(
        transformers.CLIPConfig(text_config=text, vision_config=vision, projection_dim=16)
    )
    images = transformers.CLIPImageProcessor(
        size={"shortest_edge": IMAGE}, crop_size={"height": IMAGE, "width": IMAGE}
    )
    transformers.CLIPProcessor(image_processor=images, tokenizer=tok).save_pretrained(path)
    model.save_pretrained(path)
    return path


def save_owlv2(path: Path, seed: int = 0) -> Path:
    """OWLv2 on 4 × 4 patches whose box head is zero: patch (row i, column j) predicts the box
    of side 1/4 centred on its lower right corner, ((j + 1) / 4, (i + 1) / 4), in units of the
    padded square's side (OWLv2's box bias alone)."""
    tok = tokenizer()
    text, vision = _towers(len(tok))
    torch.manual_seed(seed)
    model = transformers.Owlv2ForObjectDetection(
        transformers.Owlv2Config(text_config=text, vision_config=vision, projection_dim=WIDTH)
    )
    with torch.no_grad():  # every patch predicts its own grid box: known boxes to check
        model.box_head.dense2.weight.zero_()
        model.box_head.dense2.bias.zero_()
    images = transformers.Owlv2ImageProcessor(size={"height": IMAGE, "width": IMAGE})
    transformers.Owlv2Processor(image_processor=images, tokenizer=tok).save_pretrained(path)
    model.save_pretrained(path)
    return path


def save_sam2(path: Path, seed: int = 0) -> Path:
    """SAM 2 with a 4-stage Hiera of 8–64 channels on 128-pixel images (120 k parameters)."""
    t = transformers
    backbone = t.Sam2HieraDetConfig(
        hidden_size=8,
        num_attention_heads=1,
        image_size=[SAM_SIDE, SAM_SIDE],
        blocks_per_stage=[1, 1, 2, 1],
        embed_dim_per_stage=[8, 16, 32, 64],
        num_attention_heads_per_stage=[1, 1, 1, 1],
        window_size_per_stage=[4, 4, 4, 2],
        global_attention_blocks=[3],
        window_positional_embedding_background_size=[2, 2],
    )
    s = SAM_SIDE // 4
    vision = t.Sam2VisionConfig(
        backbone_config=backbone,
        backbone_channel_list=[64, 32, 16, 8],
        backbone_feature_sizes=[[s, s], [s // 2, s // 2], [s // 4, s // 4]],
        fpn_hidden_size=WIDTH,
    )
    prompt = t.Sam2PromptEncoderConfig(
        hidden_size=WIDTH, image_size=SAM_SIDE, patch_size=16, mask_input_channels=4
    )
    decoder = t.Sam2MaskDecoderConfig(
        hidden_size=WIDTH, mlp_dim=2 * WIDTH, num_attention_heads=2, iou_head_hidden_dim=WIDTH
    )
    config = t.Sam2Config(
        vision_config=vision, prompt_encoder_config=prompt, mask_decoder_config=decoder
    )
    torch.manual_seed(seed)
    t.Sam2Model(config).save_pretrained(path)
    return path


GD_WORDS = ("[PAD]", "[UNK]", "[CLS]", "[SEP]", "[MASK]", ".", "bottle", "chips", "crisps", "cup")


def save_grounding_dino(path: Path, seed: int = 0) -> Path:
    """Grounding DINO with a one-stage-per-level Swin of 8–64 channels, a one-layer BERT over a
    word-level vocabulary (each query word one token) and 20 box queries."""
    t = transformers
    tok = t.BertTokenizer(vocab={w: i for i, w in enumerate(GD_WORDS)})
    swin = t.SwinConfig(
        image_size=IMAGE,
        patch_size=4,
        embed_dim=8,
        depths=[1, 1, 1, 1],
        num_heads=[1, 1, 1, 1],
        window_size=2,
        out_features=["stage2", "stage3", "stage4"],
    )
    bert = t.BertConfig(
        vocab_size=len(GD_WORDS),
        hidden_size=WIDTH,
        num_hidden_layers=1,
        num_attention_heads=2,
        intermediate_size=2 * WIDTH,
        max_position_embeddings=64,
    )
    config = t.GroundingDinoConfig(
        backbone_config=swin,
        text_config=bert,
        num_queries=20,
        encoder_layers=1,
        decoder_layers=2,  # its box heads are tied across decoder layers: at least two
        encoder_ffn_dim=2 * WIDTH,
        decoder_ffn_dim=2 * WIDTH,
        encoder_attention_heads=2,
        decoder_attention_heads=2,
        d_model=WIDTH,
        max_text_len=32,
        encoder_n_points=2,
        decoder_n_points=2,
    )
    torch.manual_seed(seed)
    model = t.GroundingDinoForObjectDetection(config)
    images = t.GroundingDinoImageProcessor(size={"shortest_edge": IMAGE, "longest_edge": 2 * IMAGE})
    t.GroundingDinoProcessor(image_processor=images, tokenizer=tok).save_pretrained(path)
    model.save_pretrained(path)
    return path
