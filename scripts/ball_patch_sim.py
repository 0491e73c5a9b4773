"""The patch simulator: procedural 32 x 32 patches of ball candidates, for training the ball
verifier beside the court simulator's patches (`ballsight detect patches --sim-scenes`). A ball is
a shaded sphere with a felt seam (the tennis ball's curve), optic yellow from lime to washed out,
on a floor of any colour with grain and painted lines, sometimes among other balls; not a ball is
what the court simulator lacks and real photos show: yellow strokes (a racket's frame), bands,
rectangles, long ellipses, rings and the letters of a logo. Deterministic for a NumPy generator.
"""
import numpy as np
S = 32
yy, xx = np.mgrid[0:S, 0:S].astype(np.float32) + 0.5

def background(rng):
    """A floor of random colour with a gradient, grain, and sometimes painted lines."""
    base = rng.uniform(0, 1, 3) ** 1.3
    g = rng.normal(0, 1, 2)
    img = base[None, None, :] * (1 + 0.15 * ((xx - S / 2) * g[0] + (yy - S / 2) * g[1])[..., None] / S)
    img = img + rng.normal(0, rng.uniform(0, 0.06), (S, S, 1)) + rng.normal(0, 0.02, (S, S, 3))
    for _ in range(rng.integers(0, 3)):
        a = rng.uniform(0, np.pi); c = rng.uniform(0, S, 2); w = rng.uniform(0.5, 4)
        d = np.abs((xx - c[0]) * np.sin(a) - (yy - c[1]) * np.cos(a))
        img = np.where((d < w)[..., None], rng.uniform(0.7, 1.0) * np.ones(3), img)
    return img

def seam_points():
    t = np.linspace(0, 2 * np.pi, 200)
    a, b = 0.75, 0.25; c = 2 * np.sqrt(a * b)
    p = np.stack([a * np.cos(t) + b * np.cos(3 * t), a * np.sin(t) - b * np.sin(3 * t), c * np.sin(2 * t)], 1)
    return p / np.linalg.norm(p, axis=1, keepdims=True)
SEAM = seam_points()

def random_rotation(rng):
    q = rng.normal(size=4); q /= np.linalg.norm(q); w, x, y, z = q
    return np.array([[1-2*(y*y+z*z), 2*(x*y-z*w), 2*(x*z+y*w)], [2*(x*y+z*w), 1-2*(x*x+z*z), 2*(y*z-x*w)], [2*(x*z-y*w), 2*(y*z+x*w), 1-2*(x*x+y*y)]])

def ball_colour(rng):
    """Optic yellow under some light: hue from yellow to green-yellow, sometimes washed out."""
    rgb = np.array([rng.uniform(0.65, 0.95), rng.uniform(0.85, 1.0), rng.uniform(0.05, 0.35)])
    if rng.uniform() < 0.3:  # washed out
        rgb = rgb + (1 - rgb) * rng.uniform(0.3, 0.8)
    return rgb[::-1]  # BGR

def draw_ball(img, rng, cx, cy, r, colour=None):
    colour = ball_colour(rng) if colour is None else colour
    dx, dy = (xx - cx) / r, (yy - cy) / r
    rr = dx * dx + dy * dy
    inside = rr < 1
    nz = np.sqrt(np.clip(1 - rr, 0, 1))
    light = rng.normal(size=3); light[2] = abs(light[2]) + 0.3; light /= np.linalg.norm(light)
    shade = np.clip(dx * light[0] + dy * light[1] + nz * light[2], 0, 1) * rng.uniform(0.5, 0.9) + rng.uniform(0.15, 0.45)
    n = np.stack([dx, dy, nz], -1) @ random_rotation(rng).T
    seam = (n.reshape(-1, 3) @ SEAM.T).max(1).reshape(S, S) > np.cos(rng.uniform(0.04, 0.09))
    alb = np.where(seam[..., None] & (rng.uniform() < 0.8), np.array([0.85, 0.9, 0.9]), colour)
    alb = alb * (1 + rng.normal(0, 0.05, (S, S, 1)))
    ball = alb * shade[..., None]
    edge = np.clip((1 - np.sqrt(rr)) * r + 0.5, 0, 1)[..., None]  # anti-aliased rim
    # a soft shadow below-right of the ball
    sh = np.exp(-(((xx - cx - 0.4 * r) ** 2 + (yy - cy - 0.6 * r) ** 2) / (1.2 * r) ** 2))[..., None]
    img[:] = img * (1 - rng.uniform(0, 0.5) * sh)
    img[:] = img * (1 - edge) + ball * edge

def draw_clutter(img, rng):
    """Things that are not balls: yellow strokes (a racket's frame), bands, rectangles, long
    ellipses, rings, letters of a logo."""
    col = ball_colour(rng) if rng.uniform() < 0.7 else rng.uniform(0, 1, 3)
    kind = rng.integers(0, 5)
    c = rng.uniform(6, S - 6, 2); a = rng.uniform(0, np.pi)
    u = (xx - c[0]) * np.cos(a) + (yy - c[1]) * np.sin(a); v = -(xx - c[0]) * np.sin(a) + (yy - c[1]) * np.cos(a)
    if kind == 0:   # a stroke or band
        m = np.abs(v) < rng.uniform(1, 6)
    elif kind == 1:  # a rectangle
        m = (np.abs(u) < rng.uniform(3, 14)) & (np.abs(v) < rng.uniform(3, 14))
    elif kind == 2:  # a long ellipse
        m = (u / rng.uniform(8, 16)) ** 2 + (v / rng.uniform(2, 5)) ** 2 < 1
    elif kind == 3:  # a ring or arc
        rad = np.hypot(u, v); R = rng.uniform(6, 16)
        m = (np.abs(rad - R) < rng.uniform(1, 3)) & (np.arctan2(v, u) < rng.uniform(0, np.pi))
    else:           # blocky letters
        m = np.zeros((S, S), bool)
        for _ in range(rng.integers(2, 6)):
            p = rng.uniform(0, S, 2); w, h = rng.uniform(1, 4), rng.uniform(3, 10)
            m |= (np.abs(xx - p[0]) < w) & (np.abs(yy - p[1]) < h) if rng.uniform() < 0.5 else (np.abs(xx - p[0]) < h) & (np.abs(yy - p[1]) < w)
    img[m] = col * rng.uniform(0.6, 1.1)

def patches(n, rng):
    """n patches (uint8 BGR, N x 32 x 32 x 3) and their labels: half balls (radius 8 px,
    the candidate's radius, within its error), half clutter."""
    out = np.zeros((n, S, S, 3), np.uint8); labels = np.zeros(n, np.float32)
    for k in range(n):
        img = background(rng)
        if rng.uniform() < 0.5:
            draw_clutter(img, rng)
        is_ball = k % 2 == 0
        if is_ball:
            r = 8 * rng.uniform(0.75, 1.3)
            draw_ball(img, rng, S / 2 + rng.normal(0, 1.5), S / 2 + rng.normal(0, 1.5), r)
            for _ in range(rng.integers(0, 3)):  # neighbours
                ang = rng.uniform(0, 2 * np.pi); d = rng.uniform(2, 3) * r
                draw_ball(img, rng, S / 2 + d * np.cos(ang), S / 2 + d * np.sin(ang), r * rng.uniform(0.7, 1.2))
        else:
            draw_clutter(img, rng)
            if rng.uniform() < 0.3:  # a ball, but not where the candidate is
                ang = rng.uniform(0, 2 * np.pi)
                draw_ball(img, rng, S / 2 + 16 * np.cos(ang), S / 2 + 16 * np.sin(ang), rng.uniform(5, 9))
        out[k] = np.clip(img * 255, 0, 255).astype(np.uint8)
        labels[k] = is_ball
    return out, labels
