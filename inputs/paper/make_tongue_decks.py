#!/usr/bin/python3
"""Writes the tongue muscle-anatomy decks of inputs/paper/ (s8_*): the ICP/GIPSA tongue
(inputs/tongue/, Buchaillard, Perrier & Payan 2009; licence and citations there) with its 21
muscle bundles as element sets, each its own fibre family following its Fibers.mac polylines,
bilateral muscle groups named as in the paper (doc/tongue.md maps the names), the jaw and hyoid
attachments fixed, the named points P_A, P_P and ten control points, and the airway face set.

    /usr/bin/python3 inputs/paper/make_tongue_decks.py     # rewrites the decks in place

The decks are generated because Teuchos XML has no include: the anatomy is the same in each and
only the loads, the active group and the time stepping differ. Edit this script, not the decks.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# (data bundle, paper muscle group). Left and right bundles share one group (bilateral).
BUNDLES = [("GGP_L", "GGp"), ("GGP_R", "GGp"), ("GGM_L", "GGm"), ("GGM_R", "GGm"),
           ("GGA_L", "GGa"), ("GGA_R", "GGa"), ("STY_L", "SG"), ("STY_R", "SG"),
           ("GH_L", "GH"), ("GH_R", "GH"), ("MH_L", "MH"), ("MH_R", "MH"),
           ("HG_L", "HG"), ("HG_R", "HG"), ("VERT_L", "VT"), ("VERT_R", "VT"),
           ("TRANS_L", "TV"), ("TRANS_R", "TV"), ("IL_L", "IL"), ("IL_R", "IL"), ("SL", "SL")]
GROUPS = ["GGa", "GGm", "GGp", "SG", "GH", "MH", "HG", "VT", "TV", "IL", "SL"]

# Named points: ANSYS node ids of inputs/tongue/tongue.node and their positions (copied exactly).
POINTS = [
    ("P_A", 920, (0.05757413, 0, 0.099916)),         # tongue tip (README: node 920)
    ("P_P", 928, (0.1273674, 0, 0.08812321)),        # posterior point, midsagittal tongue base
    ("C01 mid", 913, (0.0645807, 0, 0.1049536)),     # midsagittal dorsum, tip to base
    ("C02 mid", 874, (0.07778254, 0, 0.1105348)),
    ("C03 mid", 870, (0.09481132, 0, 0.113659)),     # dorsum top (README: node 870)
    ("C04 mid", 909, (0.1123897, 0, 0.1102712)),
    ("C05 mid", 860, (0.1242321, 0, 0.09636276)),
    ("C06 mid", 929, (0.1279655, 0, 0.07885443)),    # midsagittal posterior surface, low
    ("C07 left", 143, (0.09475289, -0.01385959, 0.1133216)),   # lateral dorsum
    ("C08 right", 556, (0.09475289, 0.01385959, 0.1133216)),
    ("C09 left", 69, (0.124055, -0.0194666, 0.0962177)),       # lateral posterior surface
    ("C10 right", 482, (0.1240554, 0.0194666, 0.09621765)),
]
P_A = POINTS[0][2]
P_P = POINTS[1][2]

# The styloid anchors (data README) and the STY exit nodes: on every STY fibre of Fibers.mac, the
# mesh node next to its anchor, where the muscle enters the tongue (8 per side).
ANCHORS = {"left": (4037, (0.14984029, -0.035891287, 0.125)), "right": (4042, (0.14984029, 0.035891287, 0.125))}
# Fibre cross-section of each side's external styloglossus: the data's maximum force of the
# two-sided STY, 24 N (MuscleMaxForce.txt), as 12 N per side = phi_f T0max A with phi_f = 0.7 and
# T0max = 668.8 kPa (Table I).
SG_AREA = 12.0 / (0.7 * 668.8e3)


def styloglossus_exit_nodes():
    import re
    fibres = {}
    with open(os.path.join(HERE, "..", "tongue", "Fibers.mac"), encoding="latin-1") as f:
        for line in f:
            m = re.match(r"\s*FIBER\((\d+),(\d+),(\d+)\)\s*=\s*(\d+)", line)
            if m:
                k, fibre, muscle, node = map(int, m.groups())
                fibres.setdefault((muscle, fibre), {})[k] = node
    exits = {}
    for side, (anchor, _) in ANCHORS.items():
        nodes = set()
        for points in fibres.values():
            seq = [points[k] for k in sorted(points)]
            if anchor in seq:
                i = seq.index(anchor)
                nodes.add(seq[i - 1] if i > 0 else seq[i + 1])
        exits[side] = sorted(nodes)
        with open(os.path.join(HERE, "..", "tongue", f"styloglossus_exit_nodes_{side}.txt"), "w") as f:
            f.write("\n".join(str(n) for n in exits[side]) + "\n")
    return exits


def p(name, typ, value):
    return f'<Parameter name="{name}" type="{typ}" value="{value}"/>'


def vec(v):
    return "{" + ", ".join(repr(float(x)) if x else "0" for x in v) + "}"


class Xml:
    def __init__(self):
        self.lines, self.depth = [], 0

    def open(self, name):
        self.lines.append("  " * self.depth + f'<ParameterList name="{name}">')
        self.depth += 1

    def close(self):
        self.depth -= 1
        self.lines.append("  " * self.depth + "</ParameterList>")

    def add(self, name, typ, value):
        self.lines.append("  " * self.depth + p(name, typ, value))


def deck(name, comment, active, gravity=None, pressure=None, end_time=0.3, step=0.1, output_every=1,
         reference=None, zero_strain=None, breathing_start=None, external_sg=True, control=None,
         matrix=None, linear=None, face_sets=None, contact=None, neural=None, output=None,
         time=None, group=None, incompressibility=None, gravity_table=None, airway=None, airflow=None,
         moved_nodes=None):
    """active: {group: T0s}; groups not listed get neural input 0 (passive fibres).
    gravity: None or direction; pressure: None or p_max [Pa] (linear from P_A to P_P, ramped).
    reference: None or a Mesh/reference coordinates file (relative to the deck);
    zero_strain: None or {parameter: value} of the Zero strain section (glossa zero-strain).
    breathing_start: None (the pressure ramps over [1, 2] s) or when eq. 27's first breath starts.
    external_sg: the styloglossus also as an external muscle per side (eq. 22-23) from the styloid
    anchor to its exit nodes, driven by the SG group (passive where SG is).
    control: None or {parameter: (type, value)} of the Control section (neural control, §6.1).
    matrix: None (the Fung muscle matrix of Table I, exactly incompressible) or
    {parameter: (type, value)} of the Material section's matrix law.
    linear: None or {parameter: (type, value)} of the Linear solver section.
    face_sets: None or {name: {parameter: (type, value)}}, face sets beside 'airway'.
    contact: None or {name: {parameter: (type, value)}} of the Contact section (doc/contact.md).
    neural: None (the active groups fully activated from t = 0) or {parameter: (type, value)} of
    each active group's neural input time function (the activation then starts at 0 and follows
    u(t) through the activation dynamics).
    output: None or {parameter: (type, value)} added to the Output section.
    time, incompressibility: None or {parameter: (type, value)} added to the Time or the
    Incompressibility section (a dynamic run's analysis, integrator and tolerances).
    group: None or {parameter: (type, value)} added to each active group (e.g. its rise time).
    gravity_table: None (gravity ramped linearly over the first second) or (times, values) of a
    table time function.
    airway: None or {parameter: (type, value)} of the Airway section (doc/airway.md).
    airflow: None or {parameter: (type, value or {sublist parameter: (type, value)})} of the Airflow
    section (doc/airflow.md).
    moved_nodes: None or a Mesh/File/moved nodes file (relative to the deck): the mended tongue."""
    assert "--" not in comment
    x = Xml()
    x.lines.append("<!--")
    x.lines += ["  " + line if line else "" for line in comment.strip().split("\n")]
    x.lines.append("  Generated by inputs/paper/make_tongue_decks.py (edit that, not this file).")
    x.lines.append("-->")
    x.open("Glossa")
    x.open("Mesh")
    x.add("type", "string", "file")
    x.open("File")
    x.add("path", "string", "../tongue/tongue.node")
    if moved_nodes is not None:
        x.add("moved nodes", "string", moved_nodes)
    x.add("ANSYS components", "string", "../tongue/CreateMuscles.mac")
    x.add("ANSYS fibres", "string", "../tongue/Fibers.mac")
    x.open("ANSYS fibre anchors")
    for side, node, y in (("styloid left", 4037, -0.035891287), ("styloid right", 4042, 0.035891287)):
        x.open(side)
        x.add("id", "int", node)
        x.add("position", "Array(double)", vec((0.14984029, y, 0.125)))
        x.close()
    x.close()
    x.open("Node lists")
    for s in ("jaw", "hyoid"):
        x.open(s)
        x.add("file", "string", f"../tongue/{s}_attachment_nodes.txt")
        x.close()
    if external_sg:
        styloglossus_exit_nodes()
        for side in ANCHORS:
            x.open(f"SG exit {side}")
            x.add("file", "string", f"../tongue/styloglossus_exit_nodes_{side}.txt")
            x.close()
    x.close()
    x.close()  # File
    x.open("Face sets")
    x.open("airway")
    # Boundary faces facing posterior-superior (outward normal within 72.5 degrees of (1, 0, 1)),
    # above the hyoid attachment (z >= 0.065 m): the dorsum and the tongue base (doc/tongue.md).
    x.add("outward normal", "Array(double)", "{1, 0, 1}")
    x.add("minimum cosine", "double", 0.3)
    x.add("box min", "Array(double)", "{-1, -1, 0.065}")
    x.add("box max", "Array(double)", "{1, 1, 1}")
    x.close()
    for fname, params in (face_sets or {}).items():
        x.open(fname)
        for key, (typ, value) in params.items():
            x.add(key, typ, value)
        x.close()
    x.close()
    if reference is not None:
        x.add("reference coordinates file", "string", reference)
    x.close()  # Mesh
    x.open("Material")
    for parameter, (kind, value) in (matrix or {"type": ("string", "Fung"), "Poisson's ratio": ("double", 0.5)}).items():
        x.add(parameter, kind, value)
    x.open("Muscle groups")
    for g in GROUPS:
        x.open(g)
        x.add("T0s", "double", active.get(g, 0.1))
        if g in active:
            for key, (typ, value) in (group or {}).items():
                x.add(key, typ, value)
        if g in active and neural is not None:
            # Activation from rest: alpha follows u(t) through the activation dynamics (eq. 24).
            x.add("neural input scale", "double", 1)
            x.open("neural input")
            for key, (typ, value) in neural.items():
                x.add(key, typ, value)
            x.close()
        elif g in active:
            # Fully activated from the start: alpha = 1 throughout, so FFMR = T0s alpha = T0s.
            x.add("initial activation", "double", 1)
            x.add("neural input scale", "double", 1)
        else:
            x.add("neural input scale", "double", 0)
        x.close()
    x.close()
    x.open("Fibre families")
    for bundle, group in BUNDLES:
        x.open(bundle)
        x.add("direction field", "string", "polylines")
        # Per Gauss point: on this coarse mesh the element centroid's segment moves P_A by up to
        # 17 % under activation; sampling per point halves the distance to the refined mesh's
        # answer (doc/tongue.md, "Fibre directions").
        x.add("polyline sampling", "string", "quadrature points")
        x.add("element set", "string", bundle)
        x.add("muscle group", "string", group)
        x.close()
    x.close()
    if external_sg:
        x.open("External muscles")
        for side, (_, position) in ANCHORS.items():
            x.open(f"SG {side}")
            x.add("muscle group", "string", "SG")
            x.add("insertion node set", "string", f"SG exit {side}")
            x.add("cross-section area", "double", repr(SG_AREA))
            x.add("origin rule", "string", "fixed point")
            x.add("origin", "Array(double)", vec(position))
            x.close()
        x.close()
    x.close()  # Material
    x.open("Boundary conditions")
    for s in ("jaw", "hyoid"):
        x.open(s)
        x.add("node set", "string", s)
        x.close()
    x.close()
    x.open("Loads")
    if gravity is not None:
        x.open("weight")
        x.add("type", "string", "gravity")
        x.add("posture", "string", "custom")
        x.add("direction", "Array(double)", vec(gravity))
        x.open("time function")
        if gravity_table is None:
            x.add("type", "string", "ramp")
            x.add("ramp duration", "double", 1)
        else:
            x.add("type", "string", "table")
            x.add("times", "Array(double)", vec(gravity_table[0]))
            x.add("values", "Array(double)", vec(gravity_table[1]))
        x.close()
        x.close()
    if pressure is not None:
        x.open("airway pressure")
        x.add("type", "string", "follower pressure")
        x.add("face set", "string", "airway")
        x.add("pressure", "double", pressure)
        x.add("profile", "string", "linear")
        x.add("P_A", "Array(double)", vec(P_A))
        x.add("P_P", "Array(double)", vec(P_P))
        x.open("time function")
        if breathing_start is None:
            x.add("type", "string", "table")
            x.add("times", "Array(double)", "{0, 1, 2}")
            x.add("values", "Array(double)", "{0, 0, 1}")
        else:
            x.add("type", "string", "breathing")
            x.add("breathing period", "double", 2.5)
            x.add("breathing exponent", "double", 1.75)
            x.add("breathing start", "double", breathing_start)
        x.close()
        x.close()
    x.close()
    if contact is not None:
        x.open("Contact")
        for cname, params in contact.items():
            x.open(cname)
            for key, (typ, value) in params.items():
                x.add(key, typ, value)
            x.close()
        x.close()
    if airway is not None:
        x.open("Airway")
        for key, (typ, value) in airway.items():
            x.add(key, typ, value)
        x.close()
    if airflow is not None:
        x.open("Airflow")
        for key, (typ, value) in airflow.items():
            if typ == "sublist":
                x.open(key)
                for sub, (subtyp, subvalue) in value.items():
                    x.add(sub, subtyp, subvalue)
                x.close()
            else:
                x.add(key, typ, value)
        x.close()
    x.open("Named points")
    for pname, _, pos in POINTS:
        x.open(pname)
        x.add("position", "Array(double)", vec(pos))
        x.close()
    x.close()
    x.open("Time")
    x.add("end time", "double", end_time)
    x.add("step size", "double", step)
    for key, (typ, value) in (time or {}).items():
        x.add(key, typ, value)
    x.close()
    x.open("Incompressibility")
    x.add("method", "string", "augmented Lagrangian")
    for key, (typ, value) in (incompressibility or {}).items():
        x.add(key, typ, value)
    x.close()
    if linear is not None:
        x.open("Linear solver")
        for key, (typ, value) in linear.items():
            x.add(key, typ, value)
        x.close()
    if control is not None:
        x.open("Control")
        for key, (typ, value) in control.items():
            x.add(key, typ, value)
        x.close()
    if zero_strain is not None:
        x.open("Zero strain")
        for key, (typ, value) in zero_strain.items():
            x.add(key, typ, value)
        x.close()
    x.open("Output")
    x.add("directory", "string", f"results/{name}")
    x.add("every", "int", output_every)
    for key, (typ, value) in (output or {}).items():
        x.add(key, typ, value)
    x.close()
    x.close()
    with open(os.path.join(HERE, name + ".xml"), "w") as f:
        f.write("\n".join(x.lines) + "\n")


COMMON = """The ICP/GIPSA tongue (Buchaillard, Perrier and Payan 2009; data, licence and citations in
inputs/tongue/) with its muscle anatomy: the 21 bundles of CreateMuscles.mac are element sets,
each with its own fibre family whose direction at each quadrature point is that of the nearest
segment of the bundle's Fibers.mac polylines; left and right bundles are driven by one muscle
group (bilateral), named as in the paper (doc/tongue.md: GGa/GGm/GGp = GGA/GGM/GGP, SG = STY,
TV = TRANS, VT = VERT, SL, IL, HG, MH, GH). The styloglossus acts twice, both driven by the SG
group: inside the tongue as the fibre family of the STY bundles, and outside it as an external
muscle per side (eq. 22 and 23) from the styloid anchor to the 8 nodes where its fibres enter the
tongue, with the fibre cross-section that gives the data's maximum force (12 N per side).
Elements in no bundle are the passive Fung muscle matrix (Table I). Jaw and hyoid attachment
nodes fixed. Axes: +x posterior, +z superior.
Named points: P_A (tip, node 920), P_P (midsagittal tongue base, node 928), C01 to C10 on the
superior and posterior surface. Face set 'airway': see doc/tongue.md."""

ACTIVATION = """
Activation only (no gravity): the displacement is the muscle's own action. The active group is
fully activated from t = 0 (initial activation 1, u = 1), so FFMR = T0s alpha = T0s; the Hill
contractile element shortens at the rate its force-velocity curve allows, three 0.1 s steps."""

deck("s8_4_ggm", "Paper §8.4 (Fig. 10a): the genioglossus medius (GGm) at FFMR 10 %.\n" + COMMON + ACTIVATION +
     "\nExpected (paper): the anterior part moves down, the posterior part forward.", {"GGm": 0.1})
deck("s8_4_sg", "Paper §8.4 (Fig. 10b): the styloglossus (SG) at FFMR 25 %.\n" + COMMON + ACTIVATION + """
Expected (paper): the tongue is retracted (moves posteriorly, +x) and raised.""", {"SG": 0.25})
deck("s8_4_protrusion", "Paper §8.4 (Fig. 10c): SL, TV and VT at FFMR 7.5, 7.5 and 5 %.\n" + COMMON + ACTIVATION +
     "\nExpected (paper): the tip protrudes (moves anteriorly, -x).", {"SL": 0.075, "TV": 0.075, "VT": 0.05})
PASSIVE = """
Passive (no activation): gravity ramped over the first second, then the airway pressure, linear
from 0 at P_A to p_max at P_P on the face set 'airway', ramped from 0 at t = 1 s to its maximum
at t = 2 s (suction: p_max = -500 Pa draws the surface into the airway)."""
for posture, g in (("upright", (0, 0, -1)), ("supine", (1, 0, 0))):
    deck(f"s8_3_{posture}", f"Paper §8.3 (Figs. 8 and 9): {posture} posture, airway pressure 0 to 500 Pa.\n" + COMMON +
         PASSIVE + f"""
Gravity {posture}: along {vec(g)} in this mesh's axes. Every muscle group passive (u = 0).
Expected (paper): supine moves the tongue posteriorly; the pressure draws it backwards.""",
         {}, gravity=g, pressure=-500.0, end_time=2.0, step=0.25)

MESH_STUDY = """
Mesh dependence (bench/tongue_mesh_study.py runs this deck with Mesh/File/refine = 0, 1, 2: 740,
5920 and 47360 hexahedra). Passive (u = 0 in every group), on the imaged geometry. Coarse load
stepping, two steps per load, each converged: upright gravity along {0, 0, -1.0} ramped over
[0, 1] s"""
deck("s8_2_gravity", "Paper §8.2 (Tables III and IV analogue): mesh dependence under upright gravity.\n" + COMMON +
     MESH_STUDY + " in steps of 0.5 s.", {}, gravity=(0, 0, -1), end_time=1.0, step=0.5)
# The ArtiSynth/ICP tongue's own matrix law beside Glossa's (doc/tongue.md, "The ArtiSynth material").
ARTISYNTH = {"type": ("string", "Mooney-Rivlin"), "C10": ("double", 1037), "C20": ("double", 486),
             "bulk modulus": ("double", 10370), "volumetric energy": ("string", "quadratic")}
deck("s8_2_gravity_artisynth", "The s8_2_gravity scene with the ArtiSynth tongue's matrix law in place of the Fung muscle matrix.\n" +
     COMMON + """
The matrix is the five-parameter Mooney-Rivlin solid of the ArtiSynth/ICP tongue model (Buchaillard,
Perrier and Payan 2009, as ArtiSynth ships it): C10 = 1037 Pa, C20 = 486 Pa, the other
coefficients 0, bulk modulus 10 C10 = 10.37 kPa with U = kappa/2 (J - 1)^2 (so nearly but not
exactly incompressible, kappa/mu = 5); the passive fibre families and everything else as in
s8_2_gravity. Upright gravity along {0, 0, -1.0} ramped over [0, 1] s in steps of 0.5 s, every
muscle group passive. doc/tongue.md compares the two.""",
     {}, gravity=(0, 0, -1), end_time=1.0, step=0.5, matrix=ARTISYNTH)
deck("s8_2_gravity_pressure", "Paper §8.2 (Tables III and IV analogue): mesh dependence under upright gravity and\n"
     "the 500 Pa airway pressure.\n" + COMMON + MESH_STUDY + """, then the airway pressure as in
s8_3: linear from 0 at P_A to p_max = -500 Pa (suction) at P_P on the face set 'airway', ramped
over [1, 2] s; steps of 0.5 s.""", {}, gravity=(0, 0, -1), pressure=-500.0, end_time=2.0, step=0.5)

ZERO_STRAIN = """
Passive (no activation): upright gravity, along {0, 0, -1.0} in this mesh's axes, ramped over
[0, 1] s in four steps. Every muscle group passive (u = 0)."""
# The forward deck of the zero-strain study: glossa zero-strain reads its gravity and Zero strain
# section; with a reference coordinates file it is the s8_1 check (gravity on X0 returns X_img).
deck("s8_1_upright", "Paper §8.1 (Fig. 7a): the tongue under upright gravity, the forward problem of the\n"
     "zero-strain configuration. On the imaged geometry as read; glossa zero-strain computes the\n"
     "zero-strain configuration from this deck (doc/tongue.md, s8_1):\n"
     "  build/glossa zero-strain inputs/paper/s8_1_upright.xml method approximate or inverse\n"
     "which writes the reference coordinates that s8_1_approximate.xml and s8_1_inverse.xml use.\n" + COMMON + ZERO_STRAIN,
     {}, gravity=(0, 0, -1), end_time=1.0, step=0.25,
     zero_strain={"gravity factor": ("double", 1.2), "tolerance": ("double", 1e-3),
                  "maximum iterations": ("int", 10)})
for method in ("approximate", "inverse"):
    what = ("the paper's approximation: the imaged geometry deformed by 1.2 g opposite to gravity"
            if method == "approximate" else
            "the iterative inverse: reference coordinates updated until gravity maps them onto the\n"
            "imaged geometry, to 1e-3 of the mean element edge")
    deck(f"s8_1_{method}", f"Paper §8.1 (Fig. 7a): upright gravity on the zero-strain configuration, {method}:\n"
         f"{what}.\nThe reference coordinates are s8_1/reference_{method}.txt, written by\n"
         f"  build/glossa zero-strain inputs/paper/s8_1_upright.xml, method {method}, output that file.\n"
         "The configuration under gravity should return the imaged geometry (doc/tongue.md gives the\n"
         "distances).\n" + COMMON + ZERO_STRAIN,
         {}, gravity=(0, 0, -1), end_time=1.0, step=0.25, reference=f"s8_1/reference_{method}.txt")

BREATHING = """
Three breaths of eq. 27 after the gravity ramp (gravity over the first second): from
t0 = 1.25 s, p = p_max max(sin(2 pi (t - t0)/T), 0)^1.75 with T = 2.5 s and p_max = -350 Pa
(suction) on the face set 'airway', linear from 0 at P_A to p_max at P_P, until 8.75 s. On the
zero-strain configuration of s8_1 (s8_1/reference_inverse.txt: upright gravity on it gives back
the imaged geometry), as the paper's section 8 is; traces.csv gives each point's displacement
from the reference coordinates (ux, uy, uz) and from its imaged position (dx, dy, dz), the goal
of the controlled runs. Steps of T/8 = 0.3125 s, which land on every peak (t0 + T/4 + kT)."""
PASSIVE_BREATHING = """
Passive breathing, no control: the baseline of the controlled s8_5 runs."""
CONTROL_POINTS = ", ".join(name for name, _, _ in POINTS if name.startswith("C"))
CONTROLLED = """
Neural control of all 11 groups (paper section 6.1): at every step the controller picks the
neural inputs that keep the ten control points C01 to C10 at their imaged positions (eq. 25,
w_p = 1); the genioglossus parts are always evaluated, the other groups are pruned by their
length-weighted mean fibre stretch against its value in the zero-strain configuration (1), and
a group switched on at the previous step is kept."""
GA = """
Elitist GA (the paper's, section 6.1) on continuous genes in [0, 1]: population 14, at most 10
generations (stop after 3 without improvement), the initial population holding the previous
step's inputs, a prediction and the corners of the search space (all off, all on, each
evaluated group alone, as many as fit). The prediction: one bounded Gauss-Newton step from
the previous inputs on the converged tangent's sensitivities (the onset of each breath is met by
a prediction, not by the corners). Activation is priced at 0.2 mm per unit input squared
(effort weight 2e-4 m), so the least-activated of equally good inputs wins; seed 1 (the same
seed gives the same run).
Not the paper's binary genes: at steps of 0.3125 s an input of 1 raises alpha to
dt/(tau + dt) = 0.68 in one step (FFMR 6.8 %), far above the 0.3 to 2 % that holding the
tongue needs, so binary genes keep every group off and the tongue moves as the passive one
(doc/tongue.md, s8_5)."""
GRADIENT = """
Gradient controller: projected Gauss-Newton on continuous inputs in [0, 1] from the previous
step's, sensitivities from the converged tangent, at most 4 iterations per step."""
SUPINE_GA = """
Supine, the GA stops after 2 generations without improvement (not 3): the supine solves cost
more (measured: 27 min, eq. 25 mean 5.2 mm, against 40 min and 6.0 mm with 3). Supine the
response is strongly nonlinear (the geniohyoid pulls the tongue base forward) and the full
Gauss-Newton step can overshoot and lose to the previous inputs, which a short GA then keeps for
several steps; so the prediction is seeded at step lengths 1, 1/2 and 1/4 (a line search in
generation 0). With it the GA searches more (1,275 solves against 1,051), so to stay within
30 min on 2 ranks MueLu's aggregates and transfer operators are kept for the run (Linear
solver/MueLu reuse scope = run; the coarse matrices are still recomputed at every Newton
iteration): doc/tongue.md, s8_5."""
SCREENED_GA = """
A candidate whose start, moved along the seed's responses, turns an element over is ranked as
failed, not solved again from the step's start (Control/retry turned-over starts = false). Such
candidates lie far from the seed's inputs: in the supine run's first 2 s their objectives were
2.5-16x the step's best so far, and their solves from the step's start took a quarter of the GA's
Newton iterations. Measured over the three breaths: 0.82x the wall time supine, 0.52x upright,
other choices, every check of bench/tongue_control.py passing (doc/control.md, "Where a
candidate starts")."""
CONTROL_COMMON = {"control points": ("string", CONTROL_POINTS), "always evaluated": ("string", "GGa, GGm, GGp")}
CONTROLLERS = {
    "ga": (GA, dict(CONTROL_COMMON, **{"type": ("string", "genetic algorithm"), "genes": ("string", "continuous"),
                                        "population": ("int", 14), "generations": ("int", 10),
                                        "stagnation generations": ("int", 3), "seed": ("int", 1),
                                        "prediction seed": ("string", "Gauss-Newton step"),
                                        "effort weight": ("double", 2e-4)})),
    "gradient": (GRADIENT, dict(CONTROL_COMMON, **{"type": ("string", "gradient"),
                                                    "gradient iterations": ("int", 4)})),
}
POSTURES = (("upright", (0, 0, -1)), ("supine", (1, 0, 0)))
for posture, g in POSTURES:
    gravity = f"\nGravity {posture}: along {vec(g)} in this mesh's axes."
    deck(f"s8_5_passive_{posture}", f"Paper §8.5 (Figs. 11 and 12): {posture} posture, three 350 Pa breathing cycles.\n" +
         COMMON + BREATHING + PASSIVE_BREATHING + gravity + " Every muscle group passive (u = 0).",
         {}, gravity=g, pressure=-350.0, end_time=8.75, step=0.3125, breathing_start=1.25,
         reference="s8_1/reference_inverse.txt")
    for controller, (text, control) in CONTROLLERS.items():
        if controller == "ga":
            # A candidate whose moved start turns an element over is ranked as failed, not solved
            # again from the step's start: SCREENED_GA says why.
            control = dict(control, **{"retry turned-over starts": ("bool", "false")})
            text += SCREENED_GA
        if controller == "ga" and posture == "supine":
            # Supine solves cost more (72 s per GA step against 56 upright) and the response is
            # strongly nonlinear: SUPINE_GA says what differs and why (doc/tongue.md, s8_5).
            control = dict(control, **{"stagnation generations": ("int", 2), "prediction seed steps": ("int", 3)})
            linear = {"MueLu reuse scope": ("string", "run")}
            text += SUPINE_GA
        else:
            linear = None
        deck(f"s8_5_{controller}_{posture}",
             f"Paper §8.5 (Figs. 11 and 12): {posture} posture, three 350 Pa breathing cycles, position\n"
             "maintenance by neural control.\n" + COMMON + BREATHING + CONTROLLED + text + gravity,
             {}, gravity=g, pressure=-350.0, end_time=8.75, step=0.3125, breathing_start=1.25,
             reference="s8_1/reference_inverse.txt", control=control, linear=linear)

PALATE = """
The tongue against the palate (doc/tongue.md, "The tongue against the palate"): upright gravity
ramped over [0, 1] s on the zero-strain configuration of s8_1 (s8_1/reference_inverse.txt), which
brings the tongue to its imaged shape, clear of the palate by 1.62 mm at the nearest; then the
styloglossus (SG) and the transversus (TV), the muscles of a velar /k/ or a high /i/, at FFMR
10 %, their neural input ramped from 0 at t = 0.99 s to 1 at t = 1.49 s (the activation dynamics,
eq. 24, behind it) and held to 2 s: the dorsum rises into the palatal vault and the velum and
the tongue base is drawn back to the pharyngeal wall. (The ramp starts 0.01 s before the gravity
ramp ends so that no step ends on the knee itself, where round-off in the step's time gives an
activation of about 1e-16, too small for the Hill fibre's contractile solve; doc/tongue.md.)
Three rigid obstacles, frictionless (inputs/tongue/, same ArtiSynth model and frame):
- palate8.obj, the hard palate, velum and posterior pharyngeal wall, against the face set
  'palate side' (the boundary faces above the hyoid attachment, z >= 0.065 m, facing up or
  back), by the augmented Lagrangian, penalty 1e8 Pa/m, to the default gap tolerance (1e-3 of
  the faces' mean edge);
- ICPJaw3.obj (mandible) against 'jaw side': the boundary faces above its attachment box
  (z >= 0.085 m), the tip with them, so no attachment node is in it;
- ICPHyoid3.obj against 'hyoid side': the faces between the hyoid's attachment box and z = 0.085 m.
The bones tolerate 0.05 mm of overlap at the start (the imaged tongue's two free nodes 0.02 mm
inside the mandible). The attachment nodes stay fixed, so their faces are left out: a point inside
the bone whose nodes cannot move would never meet the gap tolerance. All three surfaces give
smoothed normals (normal field = smoothed): with faceted ones Newton stalls where the tip presses
on the mandible, its contact points switching between states, and a dorsum point hops between
two palate triangles 5 degrees apart (doc/contact.md, "Smoothed normals").
The resultant of 'palate zone' (the palate side within 12 mm of the midline, where the palate
pushes and no styloglossus insertion lies) is the force the palate exerts, and that of 'jaw zone'
(the jaw side in front of x = 0.07 m, the tip) the force the mandible exerts, for the balance check."""
deck("tongue_palate", "The tongue pressed on the palate by the styloglossus and the transversus.\n" + COMMON + PALATE,
     {"SG": 0.1, "TV": 0.1}, gravity=(0, 0, -1), end_time=2.0, step=0.05, reference="s8_1/reference_inverse.txt",
     neural={"type": ("string", "table"), "times": ("Array(double)", "{0, 0.99, 1.49}"),
             "values": ("Array(double)", "{0, 0, 1}")},
     face_sets={"palate side": {"outward normal": ("Array(double)", "{1, 0, 2}"),
                                "minimum cosine": ("double", 0.0),
                                "box min": ("Array(double)", "{-1, -1, 0.065}"),
                                "box max": ("Array(double)", "{1, 1, 1}")},
                "jaw side": {"box min": ("Array(double)", "{-1, -1, 0.085}"),
                             "box max": ("Array(double)", "{0.107, 1, 1}")},
                "palate zone": {"from": ("string", "palate side"),
                                "box min": ("Array(double)", "{-1, -0.012, -1}"),
                                "box max": ("Array(double)", "{1, 0.012, 1}")},
                "jaw zone": {"from": ("string", "jaw side"),
                             "box min": ("Array(double)", "{-1, -1, -1}"),
                             "box max": ("Array(double)", "{0.07, 1, 1}")},
                "hyoid side": {"box min": ("Array(double)", "{0.1, -1, 0.0655}"),
                               "box max": ("Array(double)", "{1, 1, 0.085}")}},
     contact={"palate": {"face set": ("string", "palate side"), "obstacle": ("string", "surface"),
                         "file": ("string", "../tongue/palate8.obj"), "penalty": ("double", 1e8),
                         "search radius": ("double", 5e-3), "normal field": ("string", "smoothed")},
              "jaw": {"face set": ("string", "jaw side"), "obstacle": ("string", "surface"),
                      "file": ("string", "../tongue/ICPJaw3.obj"), "penalty": ("double", 1e8),
                      "search radius": ("double", 5e-3), "normal field": ("string", "smoothed"),
                      "start overlap tolerance": ("double", 0.05e-3)},
              "hyoid": {"face set": ("string", "hyoid side"), "obstacle": ("string", "surface"),
                        "file": ("string", "../tongue/ICPHyoid3.obj"), "penalty": ("double", 1e8),
                        "search radius": ("double", 5e-3), "normal field": ("string", "smoothed"),
                        "start overlap tolerance": ("double", 0.05e-3)}},
     output={"resultant face sets": ("string", "palate side, palate zone, jaw zone")})

AIRWAY = """
The airway's lumen (doc/airway.md): 20 cross-sections between the face set 'airway' and the
palate and pharyngeal wall (palate8.obj), along a centreline fixed at rest from under the velum
(the dorsum's midsagittal point nearest C04, x 112 mm, z 110 mm) to the vallecula (the tongue
base's lowest midsagittal airway node, x 126.5 mm, z 70 mm); airway.csv, airway_sections.csv and
the outlines in airway_sections/. Passive (u = 0 in every group), on the zero-strain configuration
of s8_1 (s8_1/reference_inverse.txt): gravity ramped over [0, 1] s, then the airway suction of
s8_3, linear from 0 at P_A to -500 Pa at P_P on 'airway', ramped over [1, 2] s; 8 steps of
0.25 s. The palate (palate8.obj) is a frictionless contact of the face set 'palate side' (as in
tongue_palate.xml), whose area airway.csv reports."""
PALATE_SIDE = {"palate side": {"outward normal": ("Array(double)", "{1, 0, 2}"),
                               "minimum cosine": ("double", 0.0),
                               "box min": ("Array(double)", "{-1, -1, 0.065}"),
                               "box max": ("Array(double)", "{1, 1, 1}")}}
PALATE_CONTACT = {"palate": {"face set": ("string", "palate side"), "obstacle": ("string", "surface"),
                             "file": ("string", "../tongue/palate8.obj"), "penalty": ("double", 1e8),
                             "search radius": ("double", 5e-3)}}
AIRWAY_SECTION = {"face set": ("string", "airway"), "wall file": ("string", "../tongue/palate8.obj"),
                  "sections": ("int", 20), "start point": ("Array(double)", "{0.1124, 0, 0.1103}"),
                  "end point": ("Array(double)", "{0.1265, 0, 0.07}"), "contact": ("string", "palate")}
for posture, g in (("upright", (0, 0, -1)), ("supine", (1, 0, 0))):
    deck(f"airway_{posture}", f"The airway's lumen under suction, {posture}.\n" + COMMON + AIRWAY +
         f"\nGravity {posture}: along {vec(g)} in this mesh's axes.",
         {}, gravity=g, pressure=-500.0, end_time=2.0, step=0.25, reference="s8_1/reference_inverse.txt",
         face_sets=PALATE_SIDE, contact=PALATE_CONTACT, airway=AIRWAY_SECTION)

# With smoothed normals, as the Pcrit decks: the faceted palate's normals jump between facets, and
# a tongue point sliding across an edge makes Newton cycle between two states (measured: the supine
# flow deck swept to -3000 Pa stopped so at -522 Pa).
SMOOTHED_PALATE_CONTACT = {"palate": {**PALATE_CONTACT["palate"], "normal field": ("string", "smoothed")}}
FLOW_TRACHEAL = -1000.0
FLOW = f"""
The airflow through the airway (doc/airflow.md): the lumen of airway_{{posture}}.xml (20 sections
between 'airway' and palate8.obj, the palate a frictionless penalty contact of 'palate side' with
smoothed normals) is
the channel of the 1D quasi-steady flow, from the nasal end under the velum (0 Pa) to the tracheal
end at the vallecula, whose pressure is lowered from 0 at t = 1 s to {FLOW_TRACHEAL:g} Pa at t = 2 s
(a hard inspiration); the flow's pressure acts on 'airway' in place of eq. 27's, coupled to the
tongue at every step to 0.1 Pa. Passive, on the zero-strain configuration of s8_1, gravity ramped
over [0, 1] s; steps of 0.125 s. airflow.csv: the flow rate, the smallest area and each section's
pressure."""
FLOW_SECTION = {"driven by": ("string", "pressures"), "nasal pressure": ("double", 0.0),
                "tracheal pressure": ("double", FLOW_TRACHEAL),
                "tracheal pressure time function": ("sublist", {"type": ("string", "table"),
                                                                 "times": ("Array(double)", "{0, 1, 2}"),
                                                                 "values": ("Array(double)", "{0, 0, 1}")})}
for posture, g in (("upright", (0, 0, -1)), ("supine", (1, 0, 0))):
    deck(f"tongue_flow_{posture}", f"The airflow through the tongue's airway, {posture}.\n" + COMMON +
         FLOW.replace("{posture}", posture) + f"\nGravity {posture}: along {vec(g)} in this mesh's axes.",
         {}, gravity=g, end_time=2.0, step=0.125, reference="s8_1/reference_inverse.txt",
         face_sets=PALATE_SIDE, contact=SMOOTHED_PALATE_CONTACT, airway=AIRWAY_SECTION, airflow=FLOW_SECTION)

FLOW_BREATHING = """
The breath driven by the airflow (doc/airflow.md, "A breath"): s8_5's scene, but the pressure on
'airway' is the 1D flow's through the airway's lumen instead of eq. 27's prescribed profile: 20
sections between 'airway' and the palate and pharyngeal wall (palate8.obj), as in
airway_{posture}.xml, the palate a frictionless penalty contact of 'palate side' with smoothed
normals. The nasal end under the velum is at 0 Pa and the tracheal end at the vallecula follows
eq. 27's breath: from t0 = 1.25 s, p_t = -350 Pa max(sin(2 pi (t - t0)/T), 0)^1.75 with
T = 2.5 s, until 8.75 s; the flow and the tongue are coupled at every step (and every controller
candidate) to 0.1 Pa. On the zero-strain configuration of s8_1, gravity over the first second;
steps of T/8 = 0.3125 s. airflow.csv: the flow rate, the smallest area and each section's
pressure."""
FLOW_BREATH_SECTION = {"driven by": ("string", "pressures"), "nasal pressure": ("double", 0.0),
                       "tracheal pressure": ("double", -350.0),
                       "tracheal pressure time function": ("sublist", {"type": ("string", "breathing"),
                                                                        "breathing period": ("double", 2.5),
                                                                        "breathing exponent": ("double", 1.75),
                                                                        "breathing start": ("double", 1.25)})}
for posture, g in POSTURES:
    gravity = f"\nGravity {posture}: along {vec(g)} in this mesh's axes."
    common = dict(gravity=g, end_time=8.75, step=0.3125, reference="s8_1/reference_inverse.txt",
                  face_sets=PALATE_SIDE, contact=SMOOTHED_PALATE_CONTACT, airway=AIRWAY_SECTION,
                  airflow=FLOW_BREATH_SECTION)
    deck(f"s8_5_flow_passive_{posture}", f"Paper §8.5's breathing driven by the airflow, {posture} posture, passive.\n" +
         COMMON + FLOW_BREATHING.replace("{posture}", posture) + PASSIVE_BREATHING + gravity +
         " Every muscle group passive (u = 0).", {}, **common)
    deck(f"s8_5_flow_gradient_{posture}",
         f"Paper §8.5's breathing driven by the airflow, {posture} posture, position maintenance by neural\n"
         "control.\n" + COMMON + FLOW_BREATHING.replace("{posture}", posture) + CONTROLLED + GRADIENT + gravity,
         {}, control=CONTROLLERS["gradient"][1], **common)
    deck(f"s8_5_flow_ga_{posture}",
         f"Paper §8.5's breathing driven by the airflow, {posture} posture, position maintenance by neural\n"
         "control.\n" + COMMON + FLOW_BREATHING.replace("{posture}", posture) + CONTROLLED + GA + gravity,
         {}, control=CONTROLLERS["ga"][1], **common)

PCRIT_SUCTION = -4500.0
PCRIT_CLOSING_AREA = 5e-6  # m^2: the coarse tongue's closure (doc/airway.md, "Closure on the coarse tongue")
PCRIT = f"""
The airway's closing pressure Pcrit (doc/airway.md, "Pcrit"): the lumen of airway_{{posture}}.xml
(20 sections between 'airway' and palate8.obj), the palate a frictionless penalty contact of
'palate side' on the implicit surface through palate8.obj's vertices (normal field = implicit:
faceted normals stall Newton at a third of the suction, smoothed ones at -2200 Pa supine, where the
contact stiffness jumps as a point's foot crosses an edge), so the tongue cannot pass the wall; passive, on the zero-strain configuration of s8_1, gravity
ramped over [0, 1] s, then the airway suction, linear from 0 at P_A to {PCRIT_SUCTION:g} Pa at P_P
(the paper's profile; with Loads/airway pressure/profile = uniform for a uniform one) ramped over
[1, 2] s in steps of 0.125 s. Lateral walls 12.5 mm either side of the midsagittal plane (a
25 mm wide oropharynx, within the 20 to 35 mm of measured airways) bound every section's width,
which the tongue's airway faces and the wall sheet, 40 to 60 mm wide, would otherwise set. The
run raises the suction until a section closes (area below 5 mm^2, or the tongue on the wall
across the section's width), then bisects from the last open state to a bracket of 0.1 cmH2O;
summary.json: pcrit. 5 mm^2, not 1: on this coarse mesh the lumen levels off at 3 to 4 mm^2, a
sheet about 0.15 mm thick across the section that the tongue's flat faces, 5 to 8 mm across,
cannot press into a wall curved across the section (doc/airway.md, "Closure on the coarse
tongue"); 5 mm^2 is closure to the resolution of the mesh."""
for posture, g in (("upright", (0, 0, -1)), ("supine", (1, 0, 0))):
    deck(f"tongue_pcrit_{posture}", f"The tongue's airway closing pressure, {posture}.\n" + COMMON +
         PCRIT.replace("{posture}", posture) + f"\nGravity {posture}: along {vec(g)} in this mesh's axes.",
         {}, gravity=g, pressure=PCRIT_SUCTION, end_time=2.0, step=0.125, reference="s8_1/reference_inverse.txt",
         face_sets=PALATE_SIDE, contact={"palate": {**PALATE_CONTACT["palate"], "normal field": ("string", "implicit")}},
         airway={**AIRWAY_SECTION, "closing pressure load": ("string", "airway pressure"),
                 "closing area": ("double", PCRIT_CLOSING_AREA),
                 "lateral half-width": ("double", 0.0125)},
         output={"fields": ("bool", "false")})
AIRWAY_CONTROL_SUCTION = -3000.0
# s8_5's breaths at this suction, on the mended tongue's own zero-strain configuration.
AIRWAY_CONTROL_BREATHING = BREATHING.replace("-350", f"{AIRWAY_CONTROL_SUCTION:g}").replace(
    """zero-strain configuration of s8_1 (s8_1/reference_inverse.txt: upright gravity on it gives back
the imaged geometry), as the paper's section 8 is;""",
    """mended tongue's own zero-strain configuration (below: upright gravity on it gives back the
imaged geometry), as the paper's section 8 is on the published one;""")
AIRWAY_CONTROL = f"""
Neural control past the airway's closure (doc/airway.md, "Control past the closing suction"):
s8_5's three supine breaths with the wall of the Pcrit decks (the palate and pharyngeal wall a
frictionless contact on the implicit surface through palate8.obj, penalty 1e8 Pa/m and
augmented-Lagrangian enforcement, the lumen's 20
sections, lateral walls 12.5 mm either side, a section closed below 5 mm^2) and the suction
raised to p_max = {AIRWAY_CONTROL_SUCTION:g} Pa at P_P, past the suction at which the passive airway
closes. The mended tongue: the published mesh with 93 interior nodes moved by
inputs/tongue/mend_tongue.py (Mesh/File/moved nodes; surface, sets and connectivity unchanged),
on its own zero-strain configuration (s8_1/reference_inverse_mended.txt); the published mesh
folds an element before its passive airway closes in these breaths."""
AIRWAY_TERM = {"airway weight": ("double", 1000.0), "airway open area": ("double", 2e-5)}
AIRWAY_CONTROL_TERM = """
The objective adds the airway term w_A max(0, A_open - A), w_A = 1000 /m and A_open = 20 mm^2
(doc/control.md, "The airway term"), to eq. 25."""
AIRWAY_CONTROL_EFFORT = """
Activation is priced at 5 mm per unit input (effort weight 5e-3 m): the control points cannot
be held against this suction, and without the price the controller drives GGm, GGp, GH and IL
to full input, where no candidate's solve converges (t = 1.64 s)."""
AIRWAY_CONTROL_DECK = dict(gravity=(1, 0, 0), pressure=AIRWAY_CONTROL_SUCTION, end_time=8.75, step=0.3125,
                           breathing_start=1.25, reference="s8_1/reference_inverse_mended.txt",
                           moved_nodes="../tongue/tongue_mended_nodes.txt", face_sets=PALATE_SIDE,
                           contact={"palate": {**PALATE_CONTACT["palate"], "normal field": ("string", "implicit")}},
                           airway={**AIRWAY_SECTION, "closing area": ("double", PCRIT_CLOSING_AREA),
                                   "lateral half-width": ("double", 0.0125)},
                           output={"fields": ("bool", "false")})
deck("airway_control_passive_supine", "The airway past its closing suction, passive, supine.\n" + COMMON +
     AIRWAY_CONTROL_BREATHING + AIRWAY_CONTROL +
     "\nPassive: no control, the baseline whose airway closes (below 5 mm^2 from about 1.79 s to 1.95 s).\n"
     "It ends at 2.1 s, the airway open again: at 2.12 s, on the release, the tongue leaves the wall at\n"
     "a limit point of the quasi-static path (its path stiffness falls to 0.5), which load stepping\n"
     "cannot pass.", {}, **dict(AIRWAY_CONTROL_DECK, end_time=2.1))
for controller, (text, control) in CONTROLLERS.items():
    control = dict(control, **AIRWAY_TERM)
    linear = None
    if controller == "ga":
        control.update({"stagnation generations": ("int", 2), "prediction seed steps": ("int", 3)})
        linear = {"MueLu reuse scope": ("string", "run")}
        text += SUPINE_GA
    else:
        control["effort weight"] = ("double", 5e-3)
        text += AIRWAY_CONTROL_EFFORT
    deck(f"airway_control_{controller}_supine",
         f"The airway past its closing suction, supine, held open by neural control ({controller}).\n" + COMMON +
         AIRWAY_CONTROL_BREATHING + AIRWAY_CONTROL + CONTROLLED + text +
         AIRWAY_CONTROL_TERM, {}, control=control, linear=linear, **AIRWAY_CONTROL_DECK)
TWITCH = """
A styloglossus twitch (doc/dynamics.md, "The tongue twitch"): the SG group at FFMR 25 % (as
s8_4_sg) on the imaged configuration, no gravity, so the tongue starts at rest in equilibrium.
Its neural input steps to 1 at t = 0 and the activation follows eq. 24 with a rise time of
6.67 ms: 95 % of full activation in 20 ms, the onset of a fast speech gesture. Held to 0.6 s."""
TWITCH_ANALYSIS = {
    "dynamic": """
Dynamic (inertia): generalized-alpha with rho_inf = 0.5 and a consistent mass at the Fung
matrix's 1,060 kg/m^3; steps of 2 ms, about 1/40 of the tongue's slowest period under this
activation (doc/dynamics.md), and a dilatation tolerance of 1e-6, which keeps the nearly
incompressible pressure free of step-to-step oscillation. Rayleigh mass damping of 15 /s: a
damping ratio of 0.1 at that period (an assumption: the tissue's own damping is not in the
model; bench/tongue_twitch.py also runs it undamped).""",
    "static": """
Quasi-static (no inertia): the same activation history and steps, each step an equilibrium."""}
for analysis, text in TWITCH_ANALYSIS.items():
    time = {"analysis": ("string", analysis)}
    if analysis == "dynamic":
        time.update({"spectral radius": ("double", 0.5), "Rayleigh mass coefficient": ("double", 15.0)})
    deck(f"tongue_twitch_{analysis}", "A fast gesture: the styloglossus twitch, " + analysis + ".\n" + COMMON +
         TWITCH + text, {"SG": 0.25}, end_time=0.6, step=0.002,
         neural={"type": ("string", "constant")}, group={"rise time": ("double", 0.02 / 3)},
         time=time, incompressibility={"dilatation tolerance": ("double", 1e-6)},
         output={"fields": ("bool", "false")})

# s8_5's passive breathing with inertia (doc/dynamics.md, "Breathing with inertia"): gravity brought
# on smoothly, so that the breaths, not the start, are what the inertia acts on.
SMOOTH_GRAVITY = ([k / 40 for k in range(41)], [round(0.5 * (1 - math.cos(math.pi * k / 40)), 12) for k in range(41)])
deck("s8_5_passive_supine_dynamic", "Paper §8.5 (Figs. 11 and 12): supine posture, three 350 Pa breathing cycles, with inertia.\n" +
     COMMON + BREATHING + PASSIVE_BREATHING + """
Gravity supine: along {1.0, 0, 0} in this mesh's axes. Every muscle group passive (u = 0).
With inertia: the same breaths as s8_5_passive_supine, dynamic (generalized-alpha, rho_inf = 0.5,
consistent mass), steps of T/512 = 4.88 ms, which land on every step of the quasi-static run.
Gravity comes on as a half cosine (1 - cos(pi t))/2 over the first second (a table of 41 points)
instead of the linear ramp, whose kinks would set the tongue ringing before the first breath.""",
     {}, gravity=(1, 0, 0), pressure=-350.0, end_time=8.75, step=0.3125 / 64, breathing_start=1.25,
     reference="s8_1/reference_inverse.txt", gravity_table=SMOOTH_GRAVITY,
     time={"analysis": ("string", "dynamic"), "spectral radius": ("double", 0.5)},
     incompressibility={"dilatation tolerance": ("double", 1e-6)}, output={"fields": ("bool", "false")})
