"""The classic 10-bar truss problems: their data, their published optima, and a builder that makes
them trusses for truss.py. Every number carries its source beside it.

Sources (read from these files):
  [CoFE] NASTRAN_CoFE (github.com/vtpasquale/NASTRAN_CoFE, branch version5, commit a72250e):
         docs/2._Examples/b._Optimization/1._10-Bar_Truss_Sizing.md (988632c) and
         examples/1001_ten_bar_truss_optimization/ (tenBar.dat, fun1.m, fun2.m,
         runTenBarOptimizationCase1.m, runTenBarOptimizationCase2.m; 2ac9df4). They cite
         Venkayya, V. B. (1971), "Design of optimum structures", Computers & Structures 1(1),
         265-309 for the model, and Haftka, R. T. and Gurdal, Z. (1992), Elements of Structural
         Optimization, 3rd ed., pp. 238 and 244 for the two sizing problems and their optima, which
         NASTRAN_CoFE's SQP reproduces to the printed digits.
  [CoFE-N] NASTRAN_CoFE's verification run of the 10-bar truss by MSC Nastran 2019:
         testing/system_verification/001_ten_bar_truss/nastran_runs/ (tenBar.bdf, static.dat,
         modes.dat, static.f06, modes.f06; 838a601).
  [CEC]  Kumar, A., Wu, G., Ali, M. Z., Mallipeddi, R., Suganthan, P. N. and Das, S. (2020),
         "A test-suite of non-convex constrained optimization problems from the real-world and
         some baseline results", Swarm and Evolutionary Computation 56, 100693: its ten-bar truss
         with frequency constraints, as coded with its known optimal solution in DIRECTGOLib
         (github.com/blockchain-group/DIRECTGOLib, Engineering/Ten_bar_truss.m, commit 1101a32).

Units: the problems are posed in inches, pounds and pounds-force [CoFE]; they are converted here
to SI with the exact factors below, so that every test works in SI as truss.py does.
"""

import numpy as np

import truss

# Exact conversion factors (the international inch and pound of 1959, standard gravity 9.80665).
INCH = 0.0254                     # m
POUND = 0.45359237                # kg (pound-mass)
POUND_FORCE = 4.4482216152605     # N = 0.45359237 kg x 9.80665 m/s^2
PSI = POUND_FORCE / INCH ** 2     # Pa
KSI = 1000.0 * PSI                # Pa
KIP = 1000.0 * POUND_FORCE        # N
SLINCH = POUND_FORCE / INCH       # kg: 1 lbf s^2/in, NASTRAN's mass unit in inch-pound-force units

# ---------------------------------------------------------------------------------------------
# Geometry and member numbering [CoFE tenBar.dat: GRID and CROD cards; the same in CEC's gcoord
# and element arrays]: two bays of 360 in, 360 in deep. Nodes 1, 3, 5 on the upper chord, 2, 4, 6
# on the lower one; nodes 5 and 6 (x = 0) are the supports.
# ---------------------------------------------------------------------------------------------
BAY_IN = 360.0                                                      # in [CoFE tenBar.dat GRID]
NODES_IN_BAYS = [(2, 1), (2, 0), (1, 1), (1, 0), (0, 1), (0, 0)]    # (x, y) of nodes 1-6, in bays
MEMBER_ENDS = [(5, 3), (3, 1), (6, 4), (4, 2), (3, 4),              # members 1-10, 1-based nodes
               (1, 2), (5, 4), (6, 3), (3, 2), (4, 1)]              # [CoFE tenBar.dat CROD]
SUPPORT_NODES = (5, 6)                                              # [CoFE tenBar.dat SPC1 123456]
FREE_NODES = (1, 2, 3, 4)

# ---------------------------------------------------------------------------------------------
# The sizing problems [CoFE 1._10-Bar_Truss_Sizing.md, "Details"; tenBar.dat].
# ---------------------------------------------------------------------------------------------
E = 1.0e7 * PSI                          # 10^7 psi [CoFE md; tenBar.dat MAT1 1.+7]
DENSITY = 0.1 * POUND / INCH ** 3        # 0.1 lbm/in^3 [CoFE md; tenBar.dat MAT1 .1]
LOAD = 100.0 * KIP                       # 100 000 lbf down [CoFE tenBar.dat FORCE 88, -100000.]
LOADED_NODES = (2, 4)                    # the two free lower nodes [CoFE tenBar.dat FORCE 88]
STRESS_LIMIT = 25.0 * KSI                # +-25 000 psi [CoFE md; fun1.m allowableStress]
MIN_AREA = 0.1 * INCH ** 2               # 0.1 in^2 [CoFE md "Minimum area"; vlb = .1]
DISPLACEMENT_LIMIT = 2.0 * INCH          # +-2 in, vertical, nodes 1-4 [CoFE md problem 2; fun2.m]

# Problem 1, stress limits only: the optimum of Haftka & Gurdal (1992), areas printed in in^2 to
# 0.01 in^2 and weight to 0.1 lb [CoFE md table "Design in Haftka"; runTenBarOptimizationCase1.m
# haftkaOptimum].
STRESS_OPTIMUM_AREAS_IN2 = (7.94, 0.1, 8.06, 3.94, 0.1, 0.1, 5.74, 5.57, 5.57, 0.1)
STRESS_OPTIMUM_WEIGHT_LB = 1593.2        # lb [CoFE md]; 722.7 kg
# Problem 2, stress limits and vertical displacements of nodes 1-4 within +-2 in [CoFE md table
# "Design in Haftka"; runTenBarOptimizationCase2.m haftkaOptimum].
DISPLACEMENT_OPTIMUM_AREAS_IN2 = (30.52, 0.1, 23.20, 15.22, 0.1, 0.55, 7.46, 21.04, 21.53, 0.1)
DISPLACEMENT_OPTIMUM_WEIGHT_LB = 5060.85  # lb [CoFE md]; 2295.6 kg
# The printed rounding of the published numbers: areas to 0.01 in^2 (so +-0.005 in^2), weights to
# their last printed digit (+-0.05 lb and +-0.005 lb).
AREA_ROUNDING_IN2 = 0.005
STRESS_OPTIMUM_WEIGHT_ROUNDING_LB = 0.05
DISPLACEMENT_OPTIMUM_WEIGHT_ROUNDING_LB = 0.005

# ---------------------------------------------------------------------------------------------
# MSC Nastran's analysis of the 10-bar truss [CoFE-N tenBar.bdf]: every area 9.5318 in^2, 2.588
# lbf s^2/in on each free node in every direction, consistent ("coupled") mass [modes.dat
# PARAM,COUPMASS,1]. The model lies in Nastran's x-z plane with its y translations fixed, which
# is the plane truss here with z as y.
# ---------------------------------------------------------------------------------------------
NASTRAN_AREA = 9.5318 * INCH ** 2                # [CoFE-N tenBar.bdf PROD]
NASTRAN_E = 1.0e7 * PSI                          # [CoFE-N tenBar.bdf MAT1 1.E7]
NASTRAN_DENSITY = 2.59e-4 * SLINCH / INCH ** 3   # 2.59e-4 lbf s^2/in^4 [CoFE-N tenBar.bdf MAT1]
NASTRAN_NODE_MASS = 2.588 * SLINCH               # lbf s^2/in [CoFE-N tenBar.bdf PMASS, CMASS1]
# Eigenvalues w^2 [rad^2/s^2] of modes 1-8, printed to 7 significant digits [CoFE-N modes.f06,
# "R E A L   E I G E N V A L U E S"].
NASTRAN_EIGENVALUES = (3.161967e+03, 2.868724e+04, 2.931567e+04, 9.842269e+04,
                       1.277471e+05, 1.566727e+05, 1.672252e+05, 2.348492e+05)
# Total mass from the grid point weight generator, lbf s^2/in, 7 digits [CoFE-N modes.f06 and
# static.f06, "MASS AXIS SYSTEM (S)"].
NASTRAN_TOTAL_MASS = 2.071197e+01 * SLINCH
# Static subcases: a unit force on node 1, (0, -1) lbf in subcase 1 and (-1, -1) lbf in subcase
# 2 [CoFE-N tenBar.bdf FORCE 1 and 2, static.dat], and the external work (= strain energy
# u.F / 2) [in lbf] printed to 8 digits [CoFE-N static.f06, message 5293 "EXTERNAL WORK"].
NASTRAN_UNIT_LOADS = ((0.0, -1.0), (-1.0, -1.0))
NASTRAN_EXTERNAL_WORK_IN_LBF = (1.5205948e-05, 1.0881084e-05)

# ---------------------------------------------------------------------------------------------
# The frequency-constrained problem [CEC Ten_bar_truss.m, ConFun and get_xl]: SI as published.
# ---------------------------------------------------------------------------------------------
FREQ_BAY = 9.144                          # m (= 360 in) [CEC gcoord]
FREQ_E = 6.98e10                          # Pa [CEC E = 6.98e10]
FREQ_DENSITY = 2770.0                     # kg/m^3 [CEC rho = 2770]
FREQ_MIN_AREA = 0.645e-4                  # m^2 [CEC get_xl: 0.645e-4]
FREQ_ADDED_MASS = 454.0                   # kg on each node, every direction [CEC addedMass]
FREQ_LIMITS_HZ = (7.0, 15.0, 20.0)        # f1 >= 7, f2 >= 15, f3 >= 20 Hz [CEC c(1)-c(3)]
# CEC's mass matrix is the consistent one, (rho A L / 6) [[2, 0, 1, 0], [0, 2, 0, 1], ...]
# [CEC Cal_K_and_M], i.e. truss.py's "consistent" model.
FREQ_MASS_MODEL = "consistent"
# The known optimal solution [CEC Ten_bar_truss.m header, get_xmin, get_fmin]: areas [m^2] of
# members 1-10 and the structural mass [kg].
FREQ_OPTIMUM_AREAS = (0.003513223338920, 0.001471431015731, 0.003513223374772,
                      0.001471431057854, 6.450000000000295e-05, 4.558940565703403e-04,
                      0.002370087785949, 0.002370087913929, 0.001241792710714,
                      0.001241792534625)
FREQ_OPTIMUM_MASS = 524.4507606466003


def node_coordinates(bay):
    """The (6, 2) node coordinates [m] for a bay (and depth) of `bay` [m]."""
    return bay * np.array(NODES_IN_BAYS, dtype=float)


def ten_bar(areas, E, density, bay=BAY_IN * INCH, loads=None, node_mass=0.0):
    """The 10-bar truss as a truss.Truss.

    areas: the 10 member areas [m^2] in the standard numbering; E [Pa]; density [kg/m^3];
    bay [m]; loads: 1-based node -> (Fx, Fy) [N]; node_mass [kg] on each free node."""
    if len(areas) != 10:
        raise ValueError("the 10-bar truss needs 10 areas")
    members = [truss.Member(i - 1, j - 1, float(a), E, density) for (i, j), a in zip(MEMBER_ENDS, areas)]
    return truss.Truss(nodes=node_coordinates(bay), members=members,
                       pinned=[k - 1 for k in SUPPORT_NODES],
                       loads={k - 1: np.asarray(f, dtype=float) for k, f in (loads or {}).items()},
                       node_masses={k - 1: node_mass for k in FREE_NODES} if node_mass else {})


def sizing_problem(areas_in2):
    """The sizing problems' truss [CoFE] with the given areas [in^2]: 100 kip down at nodes 2
    and 4."""
    return ten_bar(np.asarray(areas_in2, dtype=float) * INCH ** 2, E, DENSITY,
                   loads={k: (0.0, -LOAD) for k in LOADED_NODES})


def nastran_model(loads=None):
    """MSC Nastran's modal and static model of the 10-bar truss [CoFE-N]; loads as in ten_bar."""
    return ten_bar([NASTRAN_AREA] * 10, NASTRAN_E, NASTRAN_DENSITY, loads=loads,
                   node_mass=NASTRAN_NODE_MASS)


def frequency_problem(areas):
    """The frequency-constrained problem's truss [CEC] with the given areas [m^2]."""
    return ten_bar(areas, FREQ_E, FREQ_DENSITY, bay=FREQ_BAY, node_mass=FREQ_ADDED_MASS)
