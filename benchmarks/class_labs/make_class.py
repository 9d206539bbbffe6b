"""A class's submissions: 40 student programs for four labs of a physics course taught with
VPython (Matter & Interactions style), for `springscene batch`'s benchmark and demo.

    python benchmarks/class_labs/make_class.py DIR

writes DIR/<lab>_<student>.py for ten students a lab and DIR/MANIFEST.tsv (file, lab,
dialect, the mistake if any, the ending expected). The labs:

- ``spring``: a block on a horizontal spring (the lab sheet's names, as
  springscene/examples/grading/spring_lab.py: ``wall``, ``ball``, ``k``, ``m``, ``L0``;
  curves labelled K, Us, K + Us; the measured period printed), so that
  ``--tests springscene/examples/grading/test_spring_lab.py`` grades them;
- ``projectile``: a ball launched through air with quadratic drag, leaving a trail;
- ``orbit``: a satellite round the Earth or the Earth round the Sun, a trail and a graph;
- ``pendulum`` (a bob on a string) and ``ramp`` (a cart pushed up an incline), with graphs.

Most are Web VPython (a ``GlowScript 3.2 VPython`` header, no imports), some VPython 7
(``from vpython import *``), a few VPython 6 (``from visual import *``). The students
vary what students vary: values, names, colours, loop style, how they keep a trail or
measure a period. Four hold a mistake of the kind a class hands in: a wrong spring
constant in the force, a typo that raises NameError about a second into the run, a loop
with no ``rate`` that never ends (a timeout) and a list of billions of times (memory).
Each runs about 3 s of program time (``rate`` loops); ``--duration 3`` ends the longer ones.

The programs are made from a fixed seed: the same DIR content every time.
"""

from __future__ import annotations

import math
import random
import sys
from dataclasses import dataclass
from pathlib import Path

SEED = 28
STUDENTS = ["abara", "baptiste", "chen", "dlamini", "eriksen", "fofana", "garcia", "haddad",
            "ivanova", "jensen", "kowalski", "li", "mbeki", "nakamura", "okafor", "petrov",
            "quispe", "rossi", "santos", "tanaka", "ueda", "varga", "wojcik", "xu", "yilmaz",
            "zhou", "adeyemi", "brennan", "costa", "dubois", "evans", "fischer", "gupta",
            "horvat", "iqbal", "jovanovic", "kim", "lopez", "moreau", "novak"]
COLOURS = ["color.red", "color.blue", "color.green", "color.orange", "color.cyan",
           "color.magenta", "color.yellow", "vec(0.6, 0.2, 0.9)", "vec(1, 0.5, 0.3)"]
HEADERS = {"gs": ["GlowScript 3.2 VPython"] * 5 + ["Web VPython 3.2"],
           "vp7": ["from vpython import *"],
           "vp6": ["from visual import *\nfrom visual.graph import *"]}
# each lab's dialects, one a student (Web VPython most, VPython 6 a few)
DIALECTS = {"spring": ["gs"] * 7 + ["vp7"] * 3,
            "projectile": ["gs"] * 7 + ["vp7"] * 2 + ["vp6"],
            "orbit": ["gs"] * 6 + ["vp7"] * 2 + ["vp6"] * 2,
            "pendulum": ["gs"] * 4 + ["vp7"] * 1 + ["vp6"],
            "ramp": ["gs"] * 2 + ["vp7"] * 2}
# (lab, the student's place in the lab) -> the mistake and the ending it should have
MISTAKES = {("spring", 4): ("wrong spring constant in the force", "ran"),
            ("projectile", 2): ("NameError at the top of the flight (about 1 s)", "error"),
            ("pendulum", 3): ("no rate() in a while True loop", "timeout"),
            ("ramp", 1): ("a list of 5e9 times (dt = 1e-9 for 1e-2)", "memory")}


@dataclass
class Student:
    """One submission: who, which lab, in which VPython, with which mistake."""
    name: str
    lab: str
    place: int                  # the student's place in the lab's list (0..)
    dialect: str                # gs, vp7 or vp6
    rng: random.Random

    @property
    def mistake(self) -> str:
        return MISTAKES.get((self.lab, self.place), ("", "ran"))[0]

    @property
    def ending(self) -> str:
        return MISTAKES.get((self.lab, self.place), ("", "ran"))[1]

    def header(self) -> str:
        return self.rng.choice(HEADERS[self.dialect])

    def vec(self) -> str:
        """The student's name for a vector: VPython 6 had only ``vector``."""
        if self.dialect == "vp6":
            return "vector"
        return "vec" if self.dialect == "gs" or self.rng.random() < 0.4 else "vector"

    def colour(self, *avoid: str) -> str:
        choice = self.rng.choice([c for c in COLOURS if c not in avoid])
        return choice.replace("vec(", "vector(") if self.dialect == "vp6" else choice

    def graph(self, title: str, xtitle: str, ytitle: str) -> str:
        make = "gdisplay" if self.dialect == "vp6" else "graph"
        return f'{make}(title="{title}", xtitle="{xtitle}", ytitle="{ytitle}")'

    def curve(self, colour: str, label: str = "") -> str:
        if self.dialect == "vp6" or not label:
            return f"gcurve(color={colour})"
        return f'gcurve(color={colour}, label="{label}")'

    def plot(self, curve: str, x: str, y: str) -> str:
        if self.dialect == "vp6" or self.rng.random() < 0.3:
            return f"{curve}.plot(pos=({x}, {y}))"
        return f"{curve}.plot({x}, {y})"

    def said(self, text: str, value: str) -> str:
        """A print of a text and a number: Web VPython students often join them with +."""
        if self.dialect == "gs" and self.rng.random() < 0.5:
            return f'print("{text} " + {value})'
        return f'print("{text}", {value})'


def _pick(rng: random.Random, *values):
    return rng.choice(values)


# ---------------------------------------------------------------- lab 1: the spring

SPRING_VALUES = [(16, 0.25), (20, 0.3), (25, 0.4), (30, 0.4), (12, 0.2), (18, 0.25),
                 (40, 0.6), (10, 0.15), (22, 0.35), (15, 0.22)]   # (k N/m, m kg): T 0.7-0.8 s


def spring(s: Student) -> str:
    """The lab sheet's horizontal spring: Euler-Cromer at dt = 1 ms, the energies plotted,
    the period measured from the block's passes through equilibrium and printed."""
    r, V = s.rng, s.vec()
    k, m = SPRING_VALUES[s.place]
    L0, A = _pick(r, 0.2, 0.25, 0.3), _pick(r, 0.05, 0.08, 0.1, 0.12)
    force_k = "k" if not s.mistake else str(k + 15)       # last week's spring's constant
    ball_col = s.colour()
    spring_col = s.colour(ball_col)
    in_loop = r.random() < 0.5          # print once three passes are counted, or at the end
    lines = [s.header(), f"# Lab 1: mass on a horizontal spring -- {s.name}",
             f'scene.title = "{_pick(r, "Spring lab", "Lab 1: block on a spring", "SHM")}"',
             f"scene.background = {_pick(r, 'color.white', 'color.black', 'vec(0.9, 0.9, 1)')}"
             .replace("vec(", f"{V}("),
             f"scene.center = {V}({L0 / 2:g}, 0, 0)", "",
             f"k = {k}      # N/m", f"m = {m}    # kg", f"L0 = {L0}   # m",
             f"A = {A}    # initial stretch, m", "dt = 0.001", "",
             f"wall = box(pos={V}(-0.05, 0, 0), size={V}(0.02, 0.15, 0.15), color=color.gray(0.6))",
             f"ball = sphere(pos={V}(L0 + A, 0, 0), radius={_pick(r, 0.03, 0.035, 0.04)}, "
             f"color={ball_col})",
             f"ball.p = m*{V}(0, 0, 0)",
             f"spring = helix(pos=wall.pos, axis=ball.pos - wall.pos, radius=0.02, "
             f"coils={_pick(r, 10, 12, 15)}, thickness=0.004, color={spring_col})", "",
             s.graph("Energy", "t (s)", "E (J)"),
             f"Kgraph = {s.curve('color.blue', 'K')}",
             f"Ugraph = {s.curve('color.red', 'Us')}",
             f"Egraph = {s.curve('color.black', 'K + Us')}", "",
             "t = 0", "crossings = []", f"while t < {_pick(r, 2.6, 2.8, 2.9)}:",
             "    rate(1000)", "    L = ball.pos - wall.pos", "    s_before = mag(L) - L0",
             f"    Fs = -{force_k}*(mag(L) - L0)*norm(L)", "    ball.p = ball.p + Fs*dt",
             "    ball.pos = ball.pos + ball.p/m*dt", "    spring.axis = ball.pos - wall.pos",
             "    t = t + dt", "    stretch = mag(ball.pos - wall.pos) - L0",
             "    if s_before < 0 and stretch >= 0:", "        crossings.append(t)"]
    if in_loop:
        lines += ["        if len(crossings) == 3:",
                  "            " + s.said("period =", "(crossings[2] - crossings[0])/2")]
    lines += ["    K = mag(ball.p)**2/(2*m)", "    Us = 0.5*k*stretch**2",
              "    " + s.plot("Kgraph", "t", "K"), "    " + s.plot("Ugraph", "t", "Us"),
              "    " + s.plot("Egraph", "t", "K + Us")]
    if not in_loop:
        lines += ["", "T = (crossings[-1] - crossings[0])/(len(crossings) - 1)",
                  s.said("measured period:", "T"),
                  s.said("expected:", "2*pi*sqrt(m/k)")]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------- lab 2: the projectile

def projectile(s: Student) -> str:
    """A ball with quadratic air drag, F = -C |v| v, launched over a field; its trail,
    some with a ball without drag beside it, a few with y(t) plotted."""
    r, V = s.rng, s.vec()
    m, R, what = _pick(r, (0.145, 0.037, "baseball"), (0.057, 0.033, "tennis ball"),
                       (0.43, 0.11, "soccer ball"), (0.046, 0.021, "golf ball"))
    v0, angle = r.choice([18, 20, 22, 24]), r.choice([35, 40, 45, 50, 55])
    C = round(0.5 * 1.2 * 0.47 * math.pi * R * R, 5)
    col, trail_col = s.colour(), s.colour()
    name = _pick(r, "ball", "proj", what.split()[0])
    lines = [s.header(), f"# Lab 2: projectile with air resistance ({what}) -- {s.name}",
             f"scene.width = {_pick(r, 800, 900, 1000)}", f"scene.height = {_pick(r, 400, 450)}",
             f"scene.center = {V}(18, 6, 0)", "scene.range = 22", "",
             f"ground = box(pos={V}(20, -0.3, 0), size={V}(50, 0.5, 6), color=color.green)",
             f"{name} = sphere(pos={V}(0, 0, 0), radius=0.6, color={col}"]
    trail = _pick(r, "make", "attach", "curve") if s.dialect != "vp6" else _pick(r, "make", "curve")
    lines[-1] += ", make_trail=True)" if trail == "make" else ")"
    if trail == "attach":
        lines.append(f"attach_trail({name}, color={trail_col})")
    elif trail == "curve":
        lines.append(f"path = curve(color={trail_col})")
    lines += [f"m = {m}        # kg", f"C = {C}    # 1/2 rho Cd A, kg/m",
              f"g = {V}(0, -9.8, 0)", f"theta = {angle}*pi/180",
              f"v = {v0}*{V}(cos(theta), sin(theta), 0)", "dt = 0.01", "t = 0"]
    compare = r.random() < 0.4
    if compare:
        lines += [f"ghost = sphere(pos={V}(0, 0, 0), radius=0.4, color=color.white, "
                  "make_trail=True)", "vg = v"]
    graphed = r.random() < 0.4
    if graphed:
        lines += [s.graph("height", "t (s)", "y (m)"), f"yplot = {s.curve('color.red')}"]
    top = s.mistake != "" or r.random() < 0.4
    if top:
        lines.append("top_printed = False")
    lines += ["", f"while {name}.pos.y >= 0:", "    rate(100)",
              "    Fdrag = -C*mag(v)*v", "    F = m*g + Fdrag", "    v = v + F/m*dt",
              f"    {name}.pos = {name}.pos + v*dt"]
    if trail == "curve":
        lines.append(f"    path.append(pos={name}.pos)")
    if compare:
        lines += ["    vg = vg + g*dt", "    ghost.pos = ghost.pos + vg*dt"]
    if graphed:
        lines.append("    " + s.plot("yplot", "t", f"{name}.pos.y"))
    if top:
        typo = name[:-1] if s.mistake else name          # 'bal' for 'ball'
        lines += ["    if v.y < 0 and not top_printed:",
                  "        " + s.said("max height:", f"{typo}.pos.y"),
                  "        top_printed = True"]
    lines += ["    t = t + dt", "", s.said("range:", f"{name}.pos.x"), s.said("time:", "t")]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------- lab 3: the orbit

def orbit(s: Student) -> str:
    """A satellite round the Earth (or the Earth round the Sun): the momentum principle
    with Newton's gravitation, a trail, and a graph of the energies or the distance."""
    r, V = s.rng, s.vec()
    sun = r.random() < 0.3
    if sun:
        big, small, M, R0, rad, srad, mass = "sun", "earth", 2e30, 1.5e11, 7e9, 3e9, 6e24
        rate_, dt = _pick(r, 200, 250), 86400 * _pick(r, 0.5, 0.6)
    else:
        big, M, R0, rad, srad = "earth", 6e24, 6.4e6 * _pick(r, 4, 5, 6, 8), 6.4e6, 1.5e6
        small, mass = _pick(r, ("craft", 1.5e4), ("sat", 1e3), ("moon", 7.3e22))
        period = 2 * math.pi * math.sqrt(R0 ** 3 / (6.7e-11 * M))
        rate_ = _pick(r, 500, 1000)
        dt = round(period / (3 * rate_) * _pick(r, 0.9, 1.2, 1.5))
    speed = math.sqrt(6.7e-11 * M / R0) * _pick(r, 0.8, 0.9, 1.0, 1.1)
    energy = r.random() < 0.6
    lines = [s.header(), f"# Lab 3: orbit of the {small} -- {s.name}",
             f"scene.range = {R0 * 1.6:.3g}",
             "G = 6.7e-11", f"M{big} = {M:g}", f"m{small} = {mass:g}",
             f"{big} = sphere(pos={V}(0, 0, 0), radius={rad:g}, color={s.colour()})",
             f"{small} = sphere(pos={V}({R0:.4g}, 0, 0), radius={srad:g}, color={s.colour()}"
             + (", make_trail=True" + _pick(r, "", ", interval=5") + ")" if s.dialect == "vp6"
                or r.random() < 0.5 else ")"),
             f"{small}.p = m{small}*{V}(0, {speed:.4g}, 0)"]
    if "make_trail" not in lines[-2]:
        lines.append(f"attach_trail({small}, color={s.colour()})")
    if energy:
        lines += [s.graph("Energy", "t (s)", "J"), f"Kcurve = {s.curve('color.red', 'K')}",
                  f"Ucurve = {s.curve('color.blue', 'U')}",
                  f"Ecurve = {s.curve('color.black', 'K + U')}"]
    else:
        lines += [s.graph("distance", "time (s)", "|r| (m)"), f"rplot = {s.curve(s.colour())}"]
    lines += [f"dt = {dt:g}", "t = 0", "", _pick(r, "while True:", "while t < 1e9:"),
              f"    rate({rate_})", f"    r = {small}.pos - {big}.pos",
              f"    Fgrav = -G*M{big}*m{small}/mag(r)**2*norm(r)",
              f"    {small}.p = {small}.p + Fgrav*dt",
              f"    {small}.pos = {small}.pos + {small}.p/m{small}*dt", "    t = t + dt"]
    if energy:
        lines += [f"    K = mag({small}.p)**2/(2*m{small})", f"    U = -G*M{big}*m{small}/mag(r)",
                  "    " + s.plot("Kcurve", "t", "K"), "    " + s.plot("Ucurve", "t", "U"),
                  "    " + s.plot("Ecurve", "t", "K + U")]
    else:
        lines.append("    " + s.plot("rplot", "t", "mag(r)"))
    lines += [f"    if mag(r) < {big}.radius:", "        " + s.said("crashed at t =", "t"),
              "        break"]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------- lab 4: pendulum or ramp

def pendulum(s: Student) -> str:
    """A bob on a string, its angle stepped with alpha = -(g/L) sin(theta), theta(t) (and
    some the energy) plotted."""
    r, V = s.rng, s.vec()
    L, deg = _pick(r, 0.5, 0.75, 1.0, 1.2), _pick(r, 20, 30, 45, 60)
    bob = _pick(r, "bob", "ball", "mass")
    lines = [s.header(), f"# Lab 4: simple pendulum, L = {L} m -- {s.name}",
             f"scene.center = {V}(0, -{L / 2:g}, 0)", f"scene.range = {L * 0.9:g}",
             f"pivot = {V}(0, 0, 0)", f"L = {L}", "g = 9.8", f"theta = {deg}*pi/180",
             "omega = 0", "",
             f"ceiling = box(pos=pivot, size={V}(0.4, 0.02, 0.2), color=color.gray(0.7))",
             f"{bob} = sphere(pos=pivot + L*{V}(sin(theta), -cos(theta), 0), radius=0.05, "
             f"color={s.colour()}" + (", make_trail=True, retain=200)" if r.random() < 0.4
                                      else ")"),
             f"string = cylinder(pos=pivot, axis={bob}.pos - pivot, radius=0.005)",
             s.graph("theta vs t", "t (s)", "theta (rad)"),
             f"thplot = {s.curve(s.colour())}", "dt = 0.01", "t = 0", ""]
    if s.mistake:
        lines += ["while True:", "    # rate(100)   too slow on my laptop"]
    else:
        lines += [_pick(r, "while True:", "while t < 20:"), "    rate(100)"]
    lines += ["    alpha = -(g/L)*sin(theta)", "    omega = omega + alpha*dt",
              "    theta = theta + omega*dt",
              f"    {bob}.pos = pivot + L*{V}(sin(theta), -cos(theta), 0)",
              f"    string.axis = {bob}.pos - pivot", "    " + s.plot("thplot", "t", "theta"),
              "    t = t + dt"]
    return "\n".join(lines) + "\n"


def ramp(s: Student) -> str:
    """A cart pushed up a ramp with friction, stepped along the incline until it is back at
    the bottom; its position and velocity along the ramp plotted."""
    r, V = s.rng, s.vec()
    deg, v0, mu = _pick(r, 5, 6, 7), _pick(r, 2.0, 2.2, 2.4), _pick(r, 0.0, 0.01, 0.02)
    lines = [s.header(), f"# Lab 4: cart on a ramp, {deg} degrees -- {s.name}",
             f"angle = {deg}*pi/180", f"along = {V}(cos(angle), sin(angle), 0)",
             "scene.center = 1.5*along", "scene.range = 1.7",
             f"ramp = box(pos=1.5*along - {V}(0, 0.03, 0), axis=3*along, "
             f"size={V}(3, 0.02, 0.3), color=color.gray(0.8))",
             f"cart = box(pos={V}(0, 0, 0), axis=0.2*along, size={V}(0.2, 0.06, 0.1), "
             f"color={s.colour()})", "m = 0.5", "g = 9.8", f"mu = {mu}",
             "s = 0.0", f"v = {v0}    # m/s up the ramp",
             s.graph("cart", "t (s)", "s (m), v (m/s)"),
             f"splot = {s.curve('color.blue', 's')}", f"vplot = {s.curve('color.red', 'v')}"]
    if s.mistake:
        lines += ["dt = 1e-9", "tmax = 5",
                  "times = [n*dt for n in range(int(tmax/dt))]   # every time step",
                  "for t in times:", "    rate(100)"]
    else:
        lines += ["dt = 0.01", "t = 0", "", "while s >= 0:", "    rate(100)"]
    lines += ["    a = -g*sin(angle) - mu*g*cos(angle)*(1 if v > 0 else -1)",
              "    v = v + a*dt", "    s = s + v*dt", "    cart.pos = s*along",
              "    " + s.plot("splot", "t", "s"), "    " + s.plot("vplot", "t", "v")]
    if not s.mistake:
        lines.append("    t = t + dt")
    lines.append(s.said("back at the bottom after", "t"))
    return "\n".join(lines) + "\n"


LABS = {"spring": spring, "projectile": projectile, "orbit": orbit,
        "pendulum": pendulum, "ramp": ramp}


def students() -> list[Student]:
    """The forty submissions, in the order of the lab lists (the same every time)."""
    rng = random.Random(SEED)
    names = iter(rng.sample(STUDENTS, len(STUDENTS)))
    made = []
    for lab, dialects in DIALECTS.items():
        for place, dialect in enumerate(dialects):
            made.append(Student(next(names), lab, place, dialect, random.Random(rng.random())))
    return made


def write_class(folder: Path) -> list[Path]:
    """Writes the programs and MANIFEST.tsv into ``folder``; the programs' paths."""
    folder.mkdir(parents=True, exist_ok=True)
    rows, paths = ["file\tlab\tdialect\tmistake\texpected"], []
    for s in students():
        path = folder / f"{s.lab}_{s.name}.py"
        path.write_text(LABS[s.lab](s))
        paths.append(path)
        rows.append(f"{path.name}\t{s.lab}\t{s.dialect}\t{s.mistake}\t{s.ending}")
    (folder / "MANIFEST.tsv").write_text("\n".join(rows) + "\n")
    return paths


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: make_class.py DIR", file=sys.stderr)
        return 2
    paths = write_class(Path(argv[0]))
    print(f"wrote {len(paths)} programs and MANIFEST.tsv into {argv[0]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
