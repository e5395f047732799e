#!/usr/bin/env python3
"""Writes the example scenes in resources/examples/ (all but default.json, which is hand-made).

The examples are data: the JSON files are what the app embeds and what the tests load. This script
is how they were laid out, kept because several of them are computed (the pyramid's rows, the
billiards rack, the asteroid field, the incline's block sitting exactly on its slope), so that a
change of a size or an angle moves everything that depends on it. Run it from the repository root:

    scripts/make_examples.py            # rewrites resources/examples/*.json (not default.json)

docs/examples.md describes each scene and the theory it can be checked against; the numbers quoted
there (angles, speeds, lengths) are the constants below.
"""

import json
import math
import pathlib
import random

OUT = pathlib.Path(__file__).resolve().parent.parent / "resources" / "examples"

G = 9.81
STEP = 1.0 / 240.0
GROUND_COLOR = "#a8a29e"
STRUCTURE_COLOR = "#78716c"

# A palette of distinct colours that read well on the canvas's off-white background. No reds:
# red is what a colliding body turns (the contract), so a red body would look like a collision.
PALETTE = ["#3b82f6", "#f59e0b", "#10b981", "#d946ef", "#8b5cf6", "#ec4899", "#14b8a6",
           "#f97316", "#6366f1", "#84cc16", "#06b6d4", "#eab308", "#a855f7", "#22c55e", "#0ea5e9"]


def num(x):
    """A number rounded to a micrometre (or a microunit), written in its shortest form."""
    r = round(float(x), 6)
    if r == 0:
        return 0
    if r == int(r) and abs(r) < 1e15:
        return int(r)
    return r


def vec(x, y):
    return [num(x), num(y)]


def scene(world, bodies, springs=(), joints=()):
    return {"format": "impetus-scene", "version": 1, "world": world, "bodies": list(bodies),
            "springs": list(springs), "joints": list(joints)}


def world(integrator="rk4", gravity=(0, -G), drag=0.0):
    return {"gravity": [num(gravity[0]), num(gravity[1])], "integrator": integrator,
            "timeStep": STEP, "drag": drag}


def body(name, shape, position, color, **extra):
    b = {"name": name, "shape": shape, "position": vec(*position)}
    b.update(extra)
    b["color"] = color
    return b


def fixed(name, shape, position, color=GROUND_COLOR, **extra):
    return body(name, shape, position, color, fixed=True, **extra)


def box(w, h):
    return {"type": "box", "width": num(w), "height": num(h)}


def circle(r):
    return {"type": "circle", "radius": num(r)}


def polygon(points):
    return {"type": "polygon", "vertices": [vec(x, y) for x, y in points]}


def centroid(points):
    """Area centroid of a simple polygon."""
    a = cx = cy = 0.0
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]):
        c = x0 * y1 - x1 * y0
        a += c
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    return cx / (3 * a), cy / (3 * a)


# ---- Formatting: one body per block, short objects and number pairs on one line ---------------

def dump(value, indent=0):
    pad = "  " * indent
    inline = json.dumps(value, ensure_ascii=False, separators=(", ", ": "))
    inline = inline.replace("{", "{ ").replace("}", " }").replace("{  }", "{}")
    if len(pad) + len(inline) <= 100 or not isinstance(value, (dict, list)):
        return inline
    inner = "  " * (indent + 1)
    if isinstance(value, list):
        if all(isinstance(v, list) for v in value):  # vertices: wrap pairs, several per line
            lines, line = [], ""
            for v in value:
                item = json.dumps(v, separators=(", ", ": "))
                if line and len(inner) + len(line) + len(item) + 2 > 100:
                    lines.append(line.rstrip(", "))
                    line = ""
                line += item + ", "
            lines.append(line.rstrip(", "))
            return "[\n" + ",\n".join(inner + l for l in lines) + "\n" + pad + "]"
        return "[\n" + ",\n".join(inner + dump(v, indent + 1) for v in value) + "\n" + pad + "]"
    items = [inner + json.dumps(k) + ": " + dump(v, indent + 1) for k, v in value.items()]
    return "{\n" + ",\n".join(items) + "\n" + pad + "}"


def write(name, data):
    path = OUT / name
    path.write_text(dump(data) + "\n", encoding="utf-8")
    print("wrote", path.relative_to(OUT.parent.parent))


# ---- The scenes --------------------------------------------------------------------------------

def incline():
    """A block sliding down a fixed 30° incline with μ = 0.2: a = g(sin θ − μ cos θ) = 3.206 m/s²."""
    theta = math.radians(30)
    mu = 0.2
    run = 7.0
    rise = run * math.tan(theta)
    ramp = [(0, 0), (run, 0), (0, rise)]  # the slope runs down to the right
    bodies = [
        fixed("floor", box(14, 0.5), (3.5, -0.25)),
        # The block leaves the ramp at about 6.7 m/s: a buffer stops it before the floor's end.
        fixed("buffer", box(0.3, 1.0), (10.35, 0.5), STRUCTURE_COLOR, restitution=0),
        fixed("incline", polygon(ramp), centroid(ramp), STRUCTURE_COLOR,
              restitution=0, friction=mu),
    ]
    # The block sits flat on the slope, 1 m down from the top, touching it (gap 0).
    w, h = 0.8, 0.5
    along = (math.cos(theta), -math.sin(theta))  # down the slope
    normal = (math.sin(theta), math.cos(theta))  # out of the slope
    s = 1.0
    contact = (s * along[0], rise + s * along[1])
    centre = (contact[0] + normal[0] * h / 2, contact[1] + normal[1] * h / 2)
    bodies.append(body("block", box(w, h), centre, "#f59e0b", angle=num(-theta), mass=2.0,
                       restitution=0, friction=mu))
    write("incline.json", scene(world("rk4"), bodies))


def projectile():
    """A ball launched at 50° and 8 m/s: range v²sin2θ/g = 6.425 m, apex v²sin²θ/(2g) = 1.914 m."""
    v, theta, r = 8.0, math.radians(50), 0.15
    x0 = -3.0
    rng = v * v * math.sin(2 * theta) / G
    bodies = [
        fixed("ground", box(14, 0.5), (2.5, -0.25)),
        # A green strip flush with the ground where the theory says the ball lands (not red: red
        # is what colliding bodies turn).
        fixed("target", box(0.6, 0.06), (x0 + rng, -0.03), "#16a34a"),
        fixed("launcher", box(0.5, 0.06), (x0, -0.03), "#1d4ed8"),
        # A backstop past the landing point: it stops the rolling ball, and its height makes the
        # canvas frame the whole flight, apex included.
        fixed("backstop", box(0.3, 2.6), (9.25, 1.3), STRUCTURE_COLOR),
        # 1 mm above the launcher, so that the launch is not counted as a collision.
        body("ball", circle(r), (x0, r + 0.001), "#3b82f6",
             velocity=vec(v * math.cos(theta), v * math.sin(theta)),
             restitution=0.5, friction=0.4),
    ]
    write("projectile.json", scene(world("rk4"), bodies))


def pendulum():
    """A bob on a 2 m rod released at 45° from a stand: T = 4√(L/g)·K(sin 22.5°) = 2.969 s."""
    length, theta0, r = 2.0, math.radians(45), 0.15
    pivot = (0.0, 2.5)
    bodies = [
        fixed("base", box(4.0, 0.2), (-1.0, -0.1)),
        fixed("post", box(0.2, 2.9), (-2.9, 1.45), STRUCTURE_COLOR),
        fixed("arm", box(3.2, 0.15), (-1.4, 2.975), STRUCTURE_COLOR),
        fixed("hook", box(0.06, 0.4), (0.0, 2.7), STRUCTURE_COLOR),
    ]
    bob = (pivot[0] + length * math.sin(theta0), pivot[1] - length * math.cos(theta0))
    bodies.append(body("bob", circle(r), bob, "#8b5cf6", mass=1.0))
    joints = [{"type": "rod", "bodyA": "bob", "anchorA": [0, 0], "bodyB": None,
               "anchorB": vec(*pivot)}]
    write("pendulum.json", scene(world("rk4"), bodies, joints=joints))


def newtons_cradle():
    """Five steel balls on 2 m rods, 1 mm apart; the first pulled back 30°."""
    count, r, gap, length = 5, 0.25, 0.001, 2.0
    pitch = 2 * r + gap
    rest_y = 0.0
    theta0 = math.radians(30)
    xs = [(i - (count - 1) / 2) * pitch for i in range(count)]
    top = rest_y + length
    bodies = [fixed("beam", box(5.0, 0.2), (0.0, top + 0.1), STRUCTURE_COLOR),
              fixed("base", box(5.0, 0.2), (0.0, rest_y - r - 0.6), GROUND_COLOR)]
    colors = PALETTE[:count]
    joints = []
    for i, x in enumerate(xs):
        pos = (x, rest_y)
        if i == 0:
            pos = (x - length * math.sin(theta0), top - length * math.cos(theta0))
        name = f"ball{i + 1}"
        bodies.append(body(name, circle(r), pos, colors[i], density=7.8, restitution=1,
                           friction=0))
        joints.append({"type": "rod", "bodyA": name, "anchorA": [0, 0], "bodyB": None,
                       "anchorB": vec(x, top)})
    write("newtons-cradle.json", scene(world("rk4"), bodies, joints=joints))


def spring_chain():
    """Left: one mass on a spring (T = 2π√(m/k)). Right: four masses in a chain, released with the
    springs at their rest length; damping settles spring i (from the top) at (4 − i)·mg/k."""
    k, m, rest = 100.0, 1.0, 0.6
    w, h = 0.5, 0.3
    bodies = [fixed("ceiling", box(5.0, 0.3), (0.0, 0.15), STRUCTURE_COLOR),
              fixed("floor", box(5.0, 0.3), (0.0, -6.15), GROUND_COLOR)]
    springs = []
    # The lone oscillator, pulled 0.4 m below its equilibrium and released.
    x = -1.5
    eq = -(rest + m * G / k) - h / 2
    bodies.append(body("weight", box(w, h), (x, eq - 0.4), "#f59e0b", mass=m))
    springs.append({"bodyA": "weight", "anchorA": vec(0, h / 2), "bodyB": None,
                    "anchorB": vec(x, 0), "stiffness": num(k), "damping": 0, "restLength": rest})
    # The chain, every spring at its rest length.
    x = 1.0
    colors = ["#3b82f6", "#6366f1", "#8b5cf6", "#a855f7"]
    y = 0.0
    above = None
    for i, color in enumerate(colors):
        y -= rest + h / 2
        name = f"mass{i + 1}"
        bodies.append(body(name, box(w, h), (x, y), color, mass=m))
        spring = {"bodyA": name, "anchorA": vec(0, h / 2), "bodyB": above,
                  "anchorB": vec(0, -h / 2) if above else vec(x, 0), "stiffness": num(k),
                  "damping": 3, "restLength": rest}
        springs.append(spring)
        above = name
        y -= h / 2
    write("spring-chain.json", scene(world("rk4"), bodies, springs=springs))


def spring():
    """A puck on an air table seen from above (no gravity), tied to the table's centre (the origin)
    by an undamped spring of zero rest length: k = 10 N/m, m = 1 kg, so ω = √(k/m) = 3.162 rad/s and
    T = 2π/ω = 1.987 s. Released 1 m out with a push of 1.5 m/s sideways, it runs round an ellipse
    of half-axes 1 m and v/ω = 0.474 m back to where it started, every period. The textbook case of
    View › Compare Integrators: explicit Euler's energy grows by (1 + ω²h²) every step."""
    k, m, r = 10.0, 1.0, 0.15
    bodies = [
        # The table's rim frames the orbit. It lies far enough out that no step, even explicit
        # Euler's at 1/30 s for its first seconds, comes within the engine's contact margins (about
        # three steps' travel): the puck then flies free, and every step is the integrator's own,
        # unsplit (no post at the centre for the same reason).
        fixed("rim bottom", box(5.4, 0.1), (0.0, -1.65), STRUCTURE_COLOR),
        fixed("rim top", box(5.4, 0.1), (0.0, 1.65), STRUCTURE_COLOR),
        fixed("rim left", box(0.1, 3.2), (-2.65, 0.0), STRUCTURE_COLOR),
        fixed("rim right", box(0.1, 3.2), (2.65, 0.0), STRUCTURE_COLOR),
        body("puck", circle(r), (1.0, 0.0), "#64748b", mass=m, velocity=vec(0, 1.5)),
    ]
    springs = [{"bodyA": "puck", "anchorA": vec(0, 0), "bodyB": None, "anchorB": vec(0, 0),
                "stiffness": num(k), "damping": 0, "restLength": 0}]
    write("spring.json", scene(world("rk4", gravity=(0, 0)), bodies, springs=springs))


def box_stack():
    """Left: ten boxes in a column, slightly narrower towards the top. Right: the book-stacking
    problem, six blocks leaning out over the edge of a table; in the ideal stack block k (from the
    top) overhangs the one below by w/(2k), so n blocks reach (w/2)·H_n past the edge. Each step
    here is 85 % of the ideal one, so that the stack stands with a margin."""
    bodies = [fixed("ground", box(10, 0.5), (0, -0.25))]
    y = 0.0
    count = 10
    for i in range(count):
        w = 1.0 - 0.04 * i
        h = 0.4
        bodies.append(body(f"box{i + 1}", box(w, h), (-2.5, y + h / 2), PALETTE[i], restitution=0,
                           friction=0.6))
        y += h
    table_top, edge = 1.0, 2.5
    bodies.append(fixed("table", box(2.0, table_top), (edge - 1.0, table_top / 2), STRUCTURE_COLOR))
    n, w, h, share = 6, 1.0, 0.3, 0.85
    right = [0.0] * (n + 1)  # right[k]: the right edge of block k, counted from the top (1)
    right[n] = edge + share * w / (2 * n)
    for k in range(n - 1, 0, -1):
        right[k] = right[k + 1] + share * w / (2 * k)
    colors = ["#0ea5e9", "#06b6d4", "#14b8a6", "#10b981", "#22c55e", "#84cc16"]
    for level in range(n):  # from the bottom up
        k = n - level
        bodies.append(body(f"book{level + 1}", box(w, h), (right[k] - w / 2, table_top + (level + 0.5) * h),
                           colors[level], restitution=0, friction=0.6))
    write("box-stack.json", scene(world("semi-implicit-euler"), bodies))


def pyramid():
    """Box2D's pyramid with a base of 20 boxes of 0.5 m: 210 boxes."""
    base, size = 20, 0.5
    bodies = [fixed("ground", box(base * size * 1.6, 0.5), (0, -0.25))]
    ramp = ["#fde68a", "#fcd34d", "#fbbf24", "#f59e0b", "#d97706"]
    for row in range(base):
        n = base - row
        for j in range(n):
            x = (j - (n - 1) / 2) * size
            y = (row + 0.5) * size
            bodies.append(body(f"r{row + 1}b{j + 1}", box(size, size), (x, y),
                               ramp[len(ramp) - 1 - row * len(ramp) // base], restitution=0,
                               friction=0.6))
    write("pyramid.json", scene(world("semi-implicit-euler"), bodies))


def billiards():
    """A pool table seen from above (no gravity): a rack of 15 balls 1 mm apart and a cue ball at
    6 m/s. Drag b = 0.03 N·s/m stands for rolling resistance (time constant m/b ≈ 5.7 s)."""
    r, m, gap = 0.028575, 0.17, 0.001
    length, width, rail = 2.54, 1.27, 0.1
    cushions = [
        ("cushion-bottom", box(length + 2 * rail, rail), (0, -(width + rail) / 2)),
        ("cushion-top", box(length + 2 * rail, rail), (0, (width + rail) / 2)),
        ("cushion-left", box(rail, width), (-(length + rail) / 2, 0)),
        ("cushion-right", box(rail, width), ((length + rail) / 2, 0)),
    ]
    bodies = [fixed(n, s, p, "#166534", restitution=0.8, friction=0.2) for n, s, p in cushions]
    balls = ["#facc15", "#2563eb", "#0d9488", "#7c3aed", "#f97316", "#16a34a", "#854d0e",
             "#111827", "#eab308", "#3b82f6", "#a3e635", "#8b5cf6", "#fb923c", "#22c55e", "#db2777"]
    apex_x = length / 4  # the foot spot
    d = 2 * r + gap
    k = 0
    for row in range(5):
        for j in range(row + 1):
            x = apex_x + row * d * math.sqrt(3) / 2
            y = (j - row / 2) * d
            bodies.append(body(f"ball{k + 1}", circle(r), (x, y), balls[k], mass=m,
                               restitution=0.95, friction=0.05))
            k += 1
    bodies.append(body("cue", circle(r), (-length / 4, 0), "#e7e5e4", mass=m,
                       velocity=[6, 0], restitution=0.95, friction=0.05))
    write("billiards.json", scene(world("semi-implicit-euler", gravity=(0, 0), drag=0.03), bodies))


def star_polygon(rng, radius, count, roughness):
    """A random simple polygon: `count` vertices at sorted angles around the origin, each at a
    random radius. Sorted angles and positive radii make it star-shaped, hence simple; a large
    `roughness` makes it concave."""
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(count))
    # Keep the vertices from bunching up: spread the angles towards an even fan.
    angles = [0.5 * a + 0.5 * (2 * math.pi * i / count) for i, a in enumerate(angles)]
    return [(radius * (1 - roughness * rng.random()) * math.cos(a),
             radius * (1 - roughness * rng.random()) * math.sin(a)) for a in angles]


def spaceship_asteroids():
    """Seed S1's scenario: a dart-shaped (concave) ship fired at 3.5 m/s through a field of
    drifting convex and concave asteroids, in zero gravity. The collision counter counts the hits."""
    rng = random.Random(2010)
    ship = [(1.1, 0), (0.25, 0.22), (-0.45, 0.6), (-0.25, 0.14), (-0.55, 0), (-0.25, -0.14),
            (-0.45, -0.6), (0.25, -0.22)]
    bodies = [body("spaceship", polygon(ship), (-7.0, 0.0), "#0ea5e9", velocity=[3.5, 0],
                   density=2.0, restitution=0.5, friction=0.3)]
    rocks = ["#a16207", "#92400e", "#78716c", "#b45309", "#57534e", "#a8a29e", "#854d0e",
             "#6b7280", "#a8a29e", "#737373"]
    placed = [((-7.0, 0.0), 1.3)]
    # A few asteroids are put on the ship's path so that a run always has hits; the rest are
    # scattered over the field.
    lanes = [(-2.5, 0.3), (0.5, -0.4), (3.5, 0.2)]
    count = 16
    attempts = 0
    while len(placed) < count + 1:
        attempts += 1
        radius = rng.uniform(0.35, 0.75)
        if lanes:
            centre = lanes.pop(0)
        else:
            centre = (rng.uniform(-4, 6), rng.uniform(-3.2, 3.2))
        if any(math.dist(centre, c) < radius + rr + 0.35 for c, rr in placed):
            continue
        i = len(placed) - 1
        concave = i % 3 != 2
        outline = star_polygon(rng, radius, rng.randint(7, 10) if concave else rng.randint(5, 7),
                               0.45 if concave else 0.15)
        if not concave:
            outline = convex_hull(outline)
        cx, cy = centroid(outline)
        position = (centre[0] + cx, centre[1] + cy)
        placed.append((centre, radius))
        bodies.append(body(f"asteroid{i + 1}", polygon(outline), position, rocks[i % len(rocks)],
                           velocity=vec(rng.uniform(-0.35, 0.35), rng.uniform(-0.35, 0.35)),
                           angularVelocity=num(rng.uniform(-0.6, 0.6)), density=1.0,
                           restitution=0.5, friction=0.3))
    write("spaceship-asteroids.json", scene(world("rk4", gravity=(0, 0)), bodies))


def convex_hull(points):
    """Andrew's monotone chain, counter-clockwise."""
    pts = sorted(points)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


if __name__ == "__main__":
    spaceship_asteroids()
    newtons_cradle()
    incline()
    projectile()
    pendulum()
    spring_chain()
    spring()
    box_stack()
    pyramid()
    billiards()
