"""Perceptual quality: CLIP (ViT-B/32) text–image similarity of a render and the scene's text.

The paper reports the cosine similarity of the two embeddings (0.297 for its indoor scenes).
Weights cannot be fetched by scenewright; the user hands a local file (``--clip-weights``).
"""

from __future__ import annotations

import importlib.util
import logging
from pathlib import Path

from scenewright.errors import BackendError, InputError, MissingExtra

log = logging.getLogger(__name__)

MODEL = "ViT-B-32"


class ClipScorer:
    """One loaded CLIP model; ``weights=None`` builds it randomly initialised (for plumbing tests only)."""

    def __init__(self, weights: str | Path | None):
        if importlib.util.find_spec("open_clip") is None:
            raise MissingExtra("CLIP scoring", "clip", "open_clip_torch")
        try:
            import open_clip
            import torch
        except (ImportError, RuntimeError) as exc:  # e.g. a torchvision built for another torch
            raise BackendError(f"open_clip is installed but cannot be imported: {exc}") from exc

        if weights is not None and not Path(weights).is_file():
            raise InputError(f"CLIP weights {weights}: no such file; give a local ViT-B/32 checkpoint")
        self._torch = torch
        self.model, _, self.preprocess = open_clip.create_model_and_transforms(
            MODEL, pretrained=str(weights) if weights is not None else None
        )
        self.model.eval()
        self.tokenizer = open_clip.get_tokenizer(MODEL)
        self.weights = str(weights) if weights is not None else None

    def score(self, text: str, image_path: str | Path) -> float:
        """Cosine similarity in [-1, 1]; long texts are cut to CLIP's 77 tokens, as every CLIP score is."""
        from PIL import Image

        torch = self._torch
        image = self.preprocess(Image.open(image_path).convert("RGB")).unsqueeze(0)
        tokens = self.tokenizer([text])
        with torch.no_grad():
            image_features = self.model.encode_image(image)
            text_features = self.model.encode_text(tokens)
        image_features = image_features / image_features.norm(dim=-1, keepdim=True)
        text_features = text_features / text_features.norm(dim=-1, keepdim=True)
        return float((image_features @ text_features.T).item())
