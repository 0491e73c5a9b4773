#!/usr/bin/python3
"""Writes the smallest ball verifier there is, for the tests and the fuzz corpus of
detect/ball_verifier.hpp: the mean yellowness (G + R - 2 B, of BGR / 255) of the
patch's middle half less that of the rest, times 40, less 3, as the logit. A
yellow ball's patch at its own size scores near 1; a grey one, or one inside a
ball (yellow all over), near 0. Needs Debian's python3-torch and python3-onnx
(scripts/setup --training).

    scripts/make_mean_colour_verifier.py OUT.onnx
"""
import sys

import torch
from torch import nn


class MeanColour(nn.Module):
    def __init__(self):
        super().__init__()
        self.pool = nn.AdaptiveAvgPool2d(1)
        self.mix = nn.Conv2d(3, 1, 1)
        with torch.no_grad():
            self.mix.weight.copy_(torch.tensor([-80.0, 40.0, 40.0]).view(1, 3, 1, 1))
            self.mix.bias.fill_(-3.0)

    def forward(self, x):
        middle = self.pool(x[:, :, 8:24, 8:24])
        rest = (self.pool(x) * 4.0 - middle) / 3.0
        return self.mix(middle - rest).flatten(1)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    torch.onnx.export(MeanColour(), torch.zeros(1, 3, 32, 32), sys.argv[1], input_names=["patch"],
                      output_names=["logit"], dynamic_axes={"patch": {0: "n"}, "logit": {0: "n"}},
                      opset_version=11)
