#!/usr/bin/env python3
"""Writes the five lesson scenes in resources/examples/ (lesson-*.json).

A lesson is a scene with a `lesson` block (docs/scene-format.md, "Lessons"): what students may
change, instructions and questions with numeric answers. The answers are computed here from the
textbook formulas, with the scene's own numbers; tests/scenes/examples_test.cpp checks each one
against the engine as well. Run it from the repository root:

    scripts/make_lessons.py            # rewrites resources/examples/lesson-*.json

It uses the layout helpers of make_examples.py (same folder), so the lessons look like the
examples they are built on. docs/examples.md explains the lessons and their numbers.
"""

import math
import sys
import pathlib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from make_examples import (G, PALETTE, STRUCTURE_COLOR, box, circle, fixed, body, num, scene, vec,  # noqa: E402
                           world, write)


def elliptic_k(k):
    """Complete elliptic integral of the first kind, K(k) = π / (2·AGM(1, √(1 − k²)))."""
    a, b = 1.0, math.sqrt(1 - k * k)
    for _ in range(30):
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def pendulum_period(length, g, amplitude):
    """T = 4√(L/g)·K(sin(θ₀/2)): the period at any amplitude (2π√(L/g) when θ₀ → 0)."""
    return 4 * math.sqrt(length / g) * elliptic_k(math.sin(amplitude / 2))


def question(prompt, answer, unit, tolerance):
    return {"prompt": prompt, "answer": round(answer, 3), "unit": unit, "tolerance": tolerance}


def lesson(title, instructions, editable=(), editable_world=(), questions=(), editable_springs=(),
           editable_joints=()):
    return {"title": title, "instructions": "\n".join(instructions), "editable": list(editable),
            "editableWorld": list(editable_world), "editableSprings": list(editable_springs),
            "editableJoints": list(editable_joints), "questions": list(questions)}


# ---- Friction on an incline -------------------------------------------------------------------

def incline_friction():
    """A block on a board tilted at 10°, μ = 0.5 for both: it starts to slide at tan θ = μ, 26.57°.

    Students turn the board and the block together (both may be moved and turned, nothing else
    changes). At 40° it slides with a = g(sin θ − μ cos θ)."""
    mu = 0.5
    alpha = math.radians(10)
    board_w, board_h = 6.0, 0.2
    # High enough that the board's lower end stays above the floor up to about 50°.
    pivot = (0.0, 2.5)
    block_w, block_h = 0.8, 0.5
    up_slope = 1.5  # the block's centre, along the board from its centre, m
    along = (math.cos(alpha), math.sin(alpha))
    normal = (-math.sin(alpha), math.cos(alpha))
    lift = board_h / 2 + block_h / 2  # block flat on the board, touching it (gap 0)
    block = (pivot[0] + up_slope * along[0] + lift * normal[0],
             pivot[1] + up_slope * along[1] + lift * normal[1])
    bodies = [
        fixed("floor", box(14, 0.5), (1.0, -0.25), friction=mu, restitution=0),
        fixed("board", box(board_w, board_h), pivot, STRUCTURE_COLOR, angle=num(alpha), friction=mu,
              restitution=0),
        body("block", box(block_w, block_h), block, "#f59e0b", angle=num(alpha), mass=2.0, friction=mu,
             restitution=0),
    ]
    critical = math.degrees(math.atan(mu))
    steep = math.radians(40)
    acceleration = G * (math.sin(steep) - mu * math.cos(steep))
    text = lesson(
        "Friction on an incline: when does the block slide?",
        [
            "A block rests on a board tilted at 10°. The block and the board have the same "
            "friction coefficient, **μ = 0.5**.",
            "",
            "1. Select the board and the block together: drag a frame around both, without the floor.",
            "2. Turn them with the **Rotate** tool (**T**): drag around their centre. Hold **Shift** "
            "to turn in steps of 15°. Click the board alone to read its angle in the attribute pane.",
            "3. Press **Play** (Space). Does the block stay or slide? Press **R** to go back, turn a "
            "little further and try again.",
            "",
            "Only the position and the angle of the board and the block can be changed; the rest is "
            "locked by the lesson.",
            "",
            "*Hint:* on the point of sliding, the largest friction force μ·N, with N = m·g·cos θ, just "
            "balances the pull down the slope, m·g·sin θ.",
        ],
        editable=[{"body": "board", "attributes": ["position", "angle"]},
                  {"body": "block", "attributes": ["position", "angle"]}],
        questions=[
            question("At what angle does the block start to slide?", critical, "°", 1.0),
            question("Turn the board to 40°. What is the block's acceleration along the board? "
                     "(Use View › New Graph and read the slope of its velocity.)",
                     acceleration, "m/s²", 0.1),
        ])
    write("lesson-incline-friction.json", {**scene(world("rk4"), bodies), "lesson": text})


# ---- Momentum in a cart crash -----------------------------------------------------------------

def cart_crash():
    """Two carts on a frictionless track meet head on: momentum m₁v₁ + m₂v₂ is kept whatever e is.

    With e = 0 they move on together at v = (m₁v₁ + m₂v₂)/(m₁ + m₂); with e = 1 they part with the
    elastic-collision velocities."""
    m1, v1 = 1.5, 2.0  # red cart, moving right
    m2, v2 = 1.0, -1.0  # blue cart, moving left
    bodies = [
        fixed("track", box(12, 0.3), (0.0, -0.15), friction=0, restitution=0),
        body("red cart", box(1.0, 0.5), (-3.0, 0.25), "#f97316", velocity=vec(v1, 0), mass=m1, friction=0,
             restitution=0),
        body("blue cart", box(0.8, 0.5), (1.0, 0.25), PALETTE[0], velocity=vec(v2, 0), mass=m2, friction=0,
             restitution=0),
    ]
    momentum = m1 * v1 + m2 * v2
    together = momentum / (m1 + m2)
    lost = 0.5 * m1 * v1 ** 2 + 0.5 * m2 * v2 ** 2 - 0.5 * (m1 + m2) * together ** 2
    blue_elastic = ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2)
    text = lesson(
        "Momentum in a cart crash",
        [
            "The red cart (1.5 kg) rolls right at 2 m/s; the blue cart (1 kg) rolls left at 1 m/s. "
            "The track has no friction. The carts' restitution is 0: they do not bounce apart.",
            "",
            "Press **Play** and watch the status bar: **p** is the total momentum, **K** the kinetic "
            "energy. Select a cart to read its velocity in the attribute pane.",
            "",
            "You may change the **restitution** of the carts (0 to 1); everything else is locked by "
            "the lesson. Press **R** to go back to the start.",
            "",
            "Take velocities to the right as positive.",
        ],
        editable=[{"body": "red cart", "attributes": ["restitution"]},
                  {"body": "blue cart", "attributes": ["restitution"]}],
        questions=[
            question("What is the total momentum of the two carts before the crash?", momentum, "kg·m/s", 0.05),
            question("With restitution 0, at what velocity do the carts move on together after the crash?",
                     together, "m/s", 0.02),
            question("How much kinetic energy does that crash (restitution 0) turn into other forms?", lost,
                     "J", 0.05),
            question("Set the restitution of both carts to 1 and run again. What is the blue cart's "
                     "velocity after the crash?", blue_elastic, "m/s", 0.05),
        ])
    write("lesson-cart-crash.json", {**scene(world("rk4"), bodies), "lesson": text})


# ---- Pendulum period against length -----------------------------------------------------------

def pendulum_length():
    """Three pendulums of 2, 1 and 0.5 m on one stand, all released at 45°.

    T = 4√(L/g)·K(sin 22.5°): 4.0% longer than 2π√(L/g) at this amplitude, and proportional to
    √L, so the 2 m pendulum takes twice as long as the 0.5 m one."""
    theta0 = math.radians(45)
    r = 0.15
    pivot_y = 2.5
    pendulums = [("long bob", 2.0, 0.0, PALETTE[4]), ("middle bob", 1.0, 3.0, PALETTE[2]),
                 ("short bob", 0.5, 5.0, PALETTE[1])]
    bodies = [
        fixed("base", box(9.2, 0.2), (1.4, -0.1)),
        fixed("post", box(0.2, 2.9), (-2.9, 1.45), STRUCTURE_COLOR),
        fixed("arm", box(8.6, 0.15), (1.3, 2.975), STRUCTURE_COLOR),
    ]
    joints = []
    for name, length, x, color in pendulums:
        bodies.append(fixed(name.replace("bob", "hook"), box(0.06, 0.4), (x, pivot_y + 0.2), STRUCTURE_COLOR))
    for name, length, x, color in pendulums:
        bob = (x + length * math.sin(theta0), pivot_y - length * math.cos(theta0))
        bodies.append(body(name, circle(r), bob, color, mass=1.0))
        joints.append({"type": "rod", "bodyA": name, "anchorA": [0, 0], "bodyB": None, "anchorB": vec(x, pivot_y)})
    t_long = pendulum_period(2.0, G, theta0)
    t_short = pendulum_period(0.5, G, theta0)
    moon = 1.62
    text = lesson(
        "Pendulum period against length",
        [
            "Three pendulums hang from one stand: 2 m, 1 m and 0.5 m long, each a 1 kg bob on a light "
            "rod. All three are released at 45°.",
            "",
            "Measure their periods: select a bob, open **View › New Graph** and read the time between "
            "two crests of x, or count swings against the time in the status bar.",
            "",
            "For small swings the textbook gives T = 2π√(L/g). At 45° the swing is not small: the "
            "period is about 4% longer, T ≈ 2π√(L/g)·(1 + θ₀²/16 + 11θ₀⁴/3072) with θ₀ in radians.",
            "",
            "You may change **gravity** (select nothing to see the world settings); the pendulums are "
            "locked by the lesson.",
        ],
        editable_world=["gravity"],
        questions=[
            question("What is the period of the 2 m pendulum?", t_long, "s", 0.03),
            question("What is the period of the 0.5 m pendulum?", t_short, "s", 0.02),
            question("How many times longer is the period of the 2 m pendulum than that of the 0.5 m one?",
                     t_long / t_short, "", 0.05),
            question("Set gravity to the Moon's, (0, −1.62) m/s², and run again. What is the period of the "
                     "2 m pendulum now?", pendulum_period(2.0, moon, theta0), "s", 0.07),
        ])
    write("lesson-pendulum-length.json", {**scene(world("rk4"), bodies, joints=joints), "lesson": text})


# ---- Period of a mass on a spring against its stiffness -----------------------------------------

def spring_period():
    """A 1 kg block on a spring of 40 N/m from a wall, on a frictionless track (no gravity), pulled
    out 0.2 m: T = 2π√(m/k) = 0.993 s. Students may change the stiffness only: four times k halves
    T, and k = 4π²m/T² gives 2 s."""
    m = 1.0
    k = 40.0
    wall_face = -2.0
    rest = 1.8
    half = 0.2
    block_x = wall_face + rest + 0.2 + half
    bodies = [
        fixed("wall", box(0.2, 1.2), (wall_face - 0.1, 0.0), STRUCTURE_COLOR),
        body("block", box(2 * half, 2 * half), (block_x, 0.0), PALETTE[4], mass=m),
    ]
    springs = [{"bodyA": "block", "anchorA": vec(-half, 0), "bodyB": "wall", "anchorB": vec(0.1, 0),
                "stiffness": k, "damping": 0, "restLength": rest}]

    def period(stiffness):
        return 2 * math.pi * math.sqrt(m / stiffness)

    text = lesson(
        "A mass on a spring: period against stiffness",
        [
            "A 1 kg block on a frictionless track (there is no gravity here) is tied to the wall by a "
            "spring. The spring is pulled out 0.2 m and let go.",
            "",
            "Measure the period: select the block, open **View › New Graph**, choose **x**, and read "
            "the time between two crests (drag a box around them to zoom), or run 10 swings and divide.",
            "",
            "You may change the spring's **stiffness** k (select the spring to see it). Everything "
            "else is locked by the lesson. Theory: T = 2π√(m/k).",
        ],
        editable_springs=[{"spring": 0, "attributes": ["stiffness"]}],
        questions=[
            question("What is the period with k = 40 N/m?", period(k), "s", 0.01),
            question("Set k to 160 N/m. What is the period now?", period(4 * k), "s", 0.01),
            question("By what factor did the period change when k became four times larger?",
                     period(4 * k) / period(k), "", 0.02),
            question("Which stiffness gives a period of 2 s?", 4 * math.pi ** 2 * m / 2.0 ** 2, "N/m", 0.2),
        ])
    write("lesson-spring-period.json",
          {**scene(world("rk4", gravity=(0, 0)), bodies, springs=springs), "lesson": text})


# ---- Tuning a pendulum: the seconds pendulum ----------------------------------------------------

def pendulum_tuning():
    """A 1 kg bob on a 1.5 m rod to a pivot, pulled 0.15 m to the side and let go. Students may move
    the rod's ends (an editableJoints entry): moving the pivot changes the length, while the bob
    stays where it is, so the amplitude is θ₀ = asin(d/L). The period is T = 4√(L/g)·K(sin(θ₀/2));
    the seconds pendulum (T = 2 s) is the L that solves T(L) = 2, a hair under g/π² = 0.994 m."""
    side = 0.15
    start_length = 1.5
    pivot = (0.0, 3.0)
    bob = (pivot[0] + side, pivot[1] - math.sqrt(start_length ** 2 - side ** 2))

    def period(length):
        return pendulum_period(length, G, math.asin(side / length))

    # T grows with L (the amplitude's shrinking takes off far less): bisect T(L) = 2 s.
    low, high = 0.5, 1.5
    for _ in range(80):
        mid = (low + high) / 2
        low, high = (mid, high) if period(mid) < 2.0 else (low, mid)
    seconds_length = (low + high) / 2
    quarter = start_length / 4
    # A beam whose underside holds the pivot, so that the view frames it (the pivot is a point of
    # the world, which moves down from under the beam with the student's edits).
    bodies = [
        fixed("floor", box(6, 0.2), (0.0, -0.1)),
        fixed("beam", box(2.0, 0.15), (0.0, pivot[1] + 0.075), STRUCTURE_COLOR),
        body("bob", circle(0.15), bob, PALETTE[4], mass=1.0),
    ]
    joints = [{"type": "rod", "bodyA": "bob", "anchorA": [0, 0], "bodyB": None, "anchorB": vec(*pivot)}]
    text = lesson(
        "Tuning a pendulum: the seconds pendulum",
        [
            "A 1 kg bob hangs on a light rod 1.5 m long. It is pulled 0.15 m to the side and let go.",
            "",
            "Measure the period: select the bob, open **View › New Graph** and read the time between "
            "two crests of x, or count swings against the time in the status bar.",
            "",
            "You may move the rod's ends: select the rod (click it) and, in the pane, change "
            "**Anchor B**, the pivot, a point of the world. Moving the pivot down shortens the rod; "
            "the pane shows its **Length**. The bob stays where it is, so a shorter rod swings wider. "
            "Everything else is locked by the lesson.",
            "",
            "Theory: T ≈ 2π√(L/g) for small swings, a little longer for wide ones.",
        ],
        editable_joints=[{"joint": 0, "attributes": ["anchors"]}],
        questions=[
            question("What is the period of the 1.5 m pendulum?", period(start_length), "s", 0.01),
            question("Move the pivot until the period is 2.00 s (a seconds pendulum: one second each way). "
                     "How long is the rod then?", seconds_length, "m", 0.01),
            question("Make the rod 0.375 m long, a quarter of its length at the start. What is the period "
                     "now?", period(quarter), "s", 0.01),
        ])
    write("lesson-pendulum-tuning.json", {**scene(world("rk4"), bodies, joints=joints), "lesson": text})


if __name__ == "__main__":
    incline_friction()
    cart_crash()
    pendulum_length()
    spring_period()
    pendulum_tuning()
