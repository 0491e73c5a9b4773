#!/usr/bin/python3
"""Trains the ball verifier: a small CNN that tells a ball candidate's patch
(`ballsight detect patches`) from anything else, and exports it to ONNX for
OpenCV's DNN module (detect/ball_verifier.hpp).

    scripts/train_ball_verifier.py --train PREFIX [--train PREFIX ...] \
        [--synthetic N] [--score PREFIX ...] --seed 1 --out model.onnx

PREFIX.npy holds uint8 patches N x 32 x 32 x 3 (BGR), PREFIX.csv their truth;
unknown ones are left out. --synthetic adds N patches of the patch simulator
(ball_patch_sim.py). The network sees BGR / 255. Deterministic for a
seed on one thread. Needs Debian's python3-torch and python3-onnx (scripts/setup
--training).
"""
import argparse
import csv
import sys

import numpy as np
import torch
from torch import nn

import ball_patch_sim


def load(prefix):
    patches = np.load(prefix + ".npy")
    with open(prefix + ".csv", newline="") as f:
        truth = [row["truth"] for row in csv.DictReader(f)]
    if len(truth) != len(patches):
        sys.exit(f"{prefix}: {len(patches)} patches but {len(truth)} rows")
    keep = np.array([t != "unknown" for t in truth])
    labels = np.array([t == "ball" for t in truth], dtype=np.float32)
    return patches[keep], labels[keep]


def network():
    return nn.Sequential(
        nn.Conv2d(3, 16, 3, padding=1), nn.ReLU(), nn.MaxPool2d(2),
        nn.Conv2d(16, 32, 3, padding=1), nn.ReLU(), nn.MaxPool2d(2),
        nn.Conv2d(32, 48, 3, padding=1), nn.ReLU(), nn.MaxPool2d(2),
        nn.Conv2d(48, 64, 4), nn.ReLU(),
        nn.Flatten(), nn.Linear(64, 1))


def augment(x, gen):
    """Colour and optics of cameras the simulator does not render: white
    balance, exposure, contrast, washed-out colour, blur, noise; flips and
    quarter turns (a ball has no up)."""
    n = x.shape[0]
    u = lambda *shape: torch.rand(*shape, generator=gen)
    x = x * (0.6 + 0.8 * u(n, 3, 1, 1))            # white balance per channel
    x = x * (0.5 + 1.0 * u(n, 1, 1, 1))            # exposure
    grey = x.mean(dim=1, keepdim=True)
    x = grey + (x - grey) * (0.1 + 1.2 * u(n, 1, 1, 1))   # saturation
    mean = x.mean(dim=(1, 2, 3), keepdim=True)
    x = mean + (x - mean) * (0.6 + 0.8 * u(n, 1, 1, 1))   # contrast
    blur = u(n) < 0.3
    if blur.any():
        k = torch.tensor([1.0, 2.0, 1.0]) / 4.0
        kernel = (k[:, None] * k[None, :]).expand(3, 1, 3, 3)
        x[blur] = nn.functional.conv2d(x[blur], kernel, padding=1, groups=3)
    x = x + torch.randn(x.shape, generator=gen) * 0.03 * u(n, 1, 1, 1)
    if u(1).item() < 0.5:
        x = x.flip(3)
    x = torch.rot90(x, int(u(1).item() * 4) % 4, dims=(2, 3))
    return x.clamp(0.0, 1.0)


def to_tensor(patches):
    return torch.from_numpy(patches).permute(0, 3, 1, 2).float() / 255.0


def average_precision(scores, labels):
    order = np.argsort(-scores)
    hits = labels[order]
    if hits.sum() == 0:
        return float("nan")
    precision = np.cumsum(hits) / np.arange(1, len(hits) + 1)
    return float((precision * hits).sum() / hits.sum())


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--train", action="append", required=True, metavar="PREFIX")
    p.add_argument("--score", action="append", default=[], metavar="PREFIX")
    p.add_argument("--synthetic", type=int, default=0, metavar="N")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--epochs", type=int, default=12)
    p.add_argument("--out", required=True)
    args = p.parse_args()

    torch.manual_seed(args.seed)
    torch.set_num_threads(1)
    gen = torch.Generator().manual_seed(args.seed)
    sets = [load(prefix) for prefix in args.train]
    if args.synthetic > 0:
        sets.append(ball_patch_sim.patches(args.synthetic, np.random.default_rng(args.seed)))
    x = to_tensor(np.concatenate([s[0] for s in sets]))
    y = torch.from_numpy(np.concatenate([s[1] for s in sets]))
    print(f"training on {len(y)} patches, {int(y.sum())} balls")

    net = network()
    optimiser = torch.optim.Adam(net.parameters(), lr=2e-3)
    # Balls are few: weigh them so that both classes count alike.
    weight = (len(y) - y.sum()) / max(y.sum(), 1)
    loss_fn = nn.BCEWithLogitsLoss(pos_weight=weight)
    for epoch in range(args.epochs):
        order = torch.randperm(len(y), generator=gen)
        total = 0.0
        for start in range(0, len(y), 256):
            batch = order[start:start + 256]
            optimiser.zero_grad()
            loss = loss_fn(net(augment(x[batch].clone(), gen)).squeeze(1), y[batch])
            loss.backward()
            optimiser.step()
            total += loss.item() * len(batch)
        print(f"epoch {epoch + 1}: loss {total / len(y):.4f}")

    net.eval()
    for prefix in args.score:
        patches, labels = load(prefix)
        with torch.no_grad():
            scores = torch.sigmoid(net(to_tensor(patches)).squeeze(1)).numpy()
        ap = average_precision(scores, labels)
        print(f"{prefix}: {int(labels.sum())} balls of {len(labels)}, average precision {ap:.3f}")

    torch.onnx.export(net, torch.zeros(1, 3, 32, 32), args.out, input_names=["patch"],
                      output_names=["logit"], dynamic_axes={"patch": {0: "n"}, "logit": {0: "n"}},
                      opset_version=11)
    print(f"-> {args.out}")


if __name__ == "__main__":
    main()
