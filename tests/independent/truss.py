"""A small linear pin-jointed truss solver, written apart from tbridge to check it.

Everything is in SI units: metres, newtons, pascals, kilograms, seconds; frequencies in hertz.
A truss lives in 2 or 3 dimensions (the width of the node coordinates). Each member is a straight
bar between two nodes that carries only axial force; the nodes are frictionless pins. Pinned nodes
have all their degrees of freedom fixed; every other node is free. The analysis is linear: small
displacements about the given geometry. A member may carry a prestress N0 (a force in equilibrium
at the given geometry without load): it adds N0 to the member's force and the geometric stiffness
(N0 / L) (I - e e^T) across it, which is all that stiffens a tensegrity's infinitesimal mechanism.

The degrees of freedom are numbered node by node: node k owns dofs k*d ... k*d + d - 1, where d is
the dimension. Only NumPy is used; the eigenproblem is reduced to a symmetric standard one by
hand (a Cholesky factor of the mass matrix) and solved with numpy.linalg.eigvalsh.
"""

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Member:
    """A bar from node i to node j (0-based): area [m^2], Young's modulus E [Pa], density [kg/m^3],
    prestress [N] (tension positive; the members' prestresses must balance at every free node)."""
    i: int
    j: int
    area: float
    E: float
    density: float
    prestress: float = 0.0


@dataclass
class Truss:
    """A pin-jointed truss.

    nodes: (n, d) coordinates [m], d = 2 or 3.
    members: the bars (Member).
    pinned: indices of the nodes whose every degree of freedom is fixed.
    loads: node index -> force vector of length d [N].
    node_masses: node index -> non-structural mass [kg], the same in every direction.
    """
    nodes: np.ndarray
    members: list
    pinned: list
    loads: dict = field(default_factory=dict)
    node_masses: dict = field(default_factory=dict)

    def __post_init__(self):
        self.nodes = np.asarray(self.nodes, dtype=float)
        if self.nodes.ndim != 2 or self.nodes.shape[1] not in (2, 3):
            raise ValueError("nodes must be an (n, 2) or (n, 3) array")
        n = len(self.nodes)
        for m in self.members:
            if not (0 <= m.i < n and 0 <= m.j < n) or m.i == m.j:
                raise ValueError("member %r joins nodes that do not exist or a node to itself" % (m,))
            if m.area <= 0 or m.E <= 0 or m.density < 0:
                raise ValueError("member %r needs a positive area and modulus" % (m,))
        for k in list(self.pinned) + list(self.loads) + list(self.node_masses):
            if not 0 <= k < n:
                raise ValueError("node %d does not exist" % k)

    @property
    def dim(self):
        """The dimension d (2 or 3)."""
        return self.nodes.shape[1]

    @property
    def n_dofs(self):
        """The number of degrees of freedom, n * d, fixed ones included."""
        return self.nodes.size


def node_dofs(truss, k):
    """The degrees of freedom of node k (an index array of length d)."""
    d = truss.dim
    return np.arange(k * d, k * d + d)


def member_dofs(truss, m):
    """The 2d degrees of freedom of member m: those of node i, then those of node j."""
    return np.concatenate([node_dofs(truss, m.i), node_dofs(truss, m.j)])


def free_dofs(truss):
    """The degrees of freedom not fixed by a pinned node, in increasing order."""
    fixed = set()
    for k in truss.pinned:
        fixed.update(node_dofs(truss, k).tolist())
    return np.array([q for q in range(truss.n_dofs) if q not in fixed], dtype=int)


def length(truss, m):
    """The length of member m [m]."""
    return float(np.linalg.norm(truss.nodes[m.j] - truss.nodes[m.i]))


def unit_vector(truss, m):
    """The unit vector from node i to node j of member m (length d, dimensionless)."""
    v = truss.nodes[m.j] - truss.nodes[m.i]
    return v / np.linalg.norm(v)


def compatibility_row(truss, m):
    """The member's elongation per unit of its 2d end displacements [m/m]: (-e, e), e its unit
    vector. Its elongation is this row times the displacements of its two ends."""
    e = unit_vector(truss, m)
    return np.concatenate([-e, e])


def member_stiffness(truss, m):
    """The (2d, 2d) global stiffness matrix of member m [N/m]: (E A / L) b b^T, with b its
    compatibility row, plus its prestress's geometric stiffness (N0 / L) [[Q, -Q], [-Q, Q]],
    Q = I - e e^T: a prestressed member resists a transverse offset of its ends."""
    b = compatibility_row(truss, m)
    e = unit_vector(truss, m)
    Q = np.eye(truss.dim) - np.outer(e, e)
    geometric = m.prestress / length(truss, m) * np.block([[Q, -Q], [-Q, Q]])
    return m.E * m.area / length(truss, m) * np.outer(b, b) + geometric


def stiffness(truss):
    """The (n d, n d) global stiffness matrix [N/m], fixed dofs included."""
    K = np.zeros((truss.n_dofs, truss.n_dofs))
    for m in truss.members:
        q = member_dofs(truss, m)
        K[np.ix_(q, q)] += member_stiffness(truss, m)
    return K


def load_vector(truss):
    """The (n d,) vector of node loads [N], fixed dofs included."""
    F = np.zeros(truss.n_dofs)
    for k, f in truss.loads.items():
        f = np.asarray(f, dtype=float)
        if f.shape != (truss.dim,):
            raise ValueError("the load on node %d must have %d components" % (k, truss.dim))
        F[node_dofs(truss, k)] += f
    return F


def displacements(truss):
    """The node displacements [m] under the loads, as an (n, d) array (zero at pinned nodes).

    Solves K_ff u_f = F_f on the free dofs f. Raises numpy.linalg.LinAlgError if the free part
    of K is singular (a mechanism)."""
    f = free_dofs(truss)
    K = stiffness(truss)
    u = np.zeros(truss.n_dofs)
    u[f] = np.linalg.solve(K[np.ix_(f, f)], load_vector(truss)[f])
    return u.reshape(truss.nodes.shape)


def member_forces(truss, u):
    """The axial force of every member [N], tension positive, from the (n, d) displacements u [m]:
    N = N0 + (E A / L) * elongation."""
    u = np.asarray(u, dtype=float).reshape(-1)
    return np.array([m.prestress + m.E * m.area / length(truss, m) * compatibility_row(truss, m) @ u[member_dofs(truss, m)]
                     for m in truss.members])


def stresses(truss, u):
    """The axial stress of every member [Pa], tension positive: N / A."""
    return member_forces(truss, u) / np.array([m.area for m in truss.members])


def reactions(truss, u):
    """The support reactions [N] as an (n, d) array: K u - F - E N0 at every node, E N0 the pull
    of the members' prestresses (equilibrium_matrix). At a pinned node this is the force its
    support applies to the truss; at a free node it is the residual of the solve, zero to
    round-off."""
    u = np.asarray(u, dtype=float).reshape(-1)
    pull = equilibrium_matrix(truss) @ np.array([m.prestress for m in truss.members])
    return (stiffness(truss) @ u - load_vector(truss) - pull).reshape(truss.nodes.shape)


def equilibrium_matrix(truss):
    """The (n d, members) equilibrium matrix: column k holds the forces member k exerts on its end
    nodes per newton of tension (-b^T, b its compatibility row: a tension pulls each end towards
    the other), at every node, pinned ones included."""
    A = np.zeros((truss.n_dofs, len(truss.members)))
    for k, m in enumerate(truss.members):
        A[member_dofs(truss, m), k] = -compatibility_row(truss, m)
    return A


def self_stress_states(truss, tol=1e-10):
    """An orthonormal basis (members, s) of the member forces in equilibrium at every node without
    load or support: the null space of the equilibrium matrix, from its SVD (singular values below
    tol times the largest count as zero)."""
    A = equilibrium_matrix(truss)
    _, sv, vt = np.linalg.svd(A)
    rank = int(np.sum(sv > tol * sv[0]))
    return vt[rank:].T


def member_masses(truss):
    """The mass of every member [kg]: density * area * length."""
    return np.array([m.density * m.area * length(truss, m) for m in truss.members])


def mass(truss):
    """The structural mass [kg]: the sum of the members' masses, without the node masses."""
    return float(member_masses(truss).sum())


def total_mass(truss):
    """The structural mass plus the non-structural node masses [kg]."""
    return mass(truss) + float(sum(truss.node_masses.values()))


# The member mass matrices, each given by (a, b): with m = rho A L, e the member's unit vector,
# P = e e^T its axial projector and Q = I - P the transverse one, the (2d, 2d) matrix is
#     m [[a P + b Q, (1/2 - a) P + (1/2 - b) Q], [(1/2 - a) P + (1/2 - b) Q, a P + b Q]],
# which carries a rigid translation with the whole mass m whatever a and b are.
MASS_MODELS = {
    # Half of rho A L at each end, in every direction: a diagonal matrix.
    "lumped": (1.0 / 2.0, 1.0 / 2.0),
    # The consistent matrix of a bar whose displacement is interpolated linearly along it in every
    # direction, axial and transverse alike: (rho A L / 6) [[2 I, I], [I, 2 I]], I the d x d
    # identity.
    "consistent": (1.0 / 3.0, 1.0 / 3.0),
    # MSC Nastran's coupled mass of a CROD (PARAM,COUPMASS,1): axially the mean of the lumped and
    # the consistent matrices, (rho A L / 12) [[5, 1], [1, 5]]; transversely lumped. As written in
    # NASTRAN_CoFE's Crod.m (crodMat); the tests hold it to MSC Nastran's printed eigenvalues.
    "nastran_crod": (5.0 / 12.0, 1.0 / 2.0),
}


def member_mass_matrix(truss, m, model="consistent"):
    """The (2d, 2d) mass matrix of member m [kg] in the mass model `model` (see MASS_MODELS)."""
    if model not in MASS_MODELS:
        raise ValueError("mass model must be one of %s, not %r" % (sorted(MASS_MODELS), model))
    a, b = MASS_MODELS[model]
    e = unit_vector(truss, m)
    P = np.outer(e, e)
    Q = np.eye(truss.dim) - P
    diagonal = a * P + b * Q
    coupling = (0.5 - a) * P + (0.5 - b) * Q
    return m.density * m.area * length(truss, m) * np.block([[diagonal, coupling], [coupling, diagonal]])


def mass_matrix(truss, model="consistent"):
    """The (n d, n d) global mass matrix [kg], fixed dofs included: the members' matrices in the
    mass model `model` ("lumped", "consistent" or "nastran_crod"; see MASS_MODELS) plus the
    non-structural node masses on the diagonal, the same in every direction."""
    M = np.zeros((truss.n_dofs, truss.n_dofs))
    for m in truss.members:
        q = member_dofs(truss, m)
        M[np.ix_(q, q)] += member_mass_matrix(truss, m, model)
    for k, mk in truss.node_masses.items():
        q = node_dofs(truss, k)
        M[q, q] += mk
    return M


def eigenvalues(truss, model="consistent"):
    """The eigenvalues w^2 [rad^2/s^2] of K phi = w^2 M phi on the free dofs, ascending.

    M_ff = L L^T (Cholesky: M_ff must be positive definite, as it is when every free node carries
    some mass, its own or a member's; numpy.linalg.LinAlgError otherwise); then w^2 are the
    eigenvalues of the symmetric L^-1 K_ff L^-T. For a diagonal M this is M^-1/2 K M^-1/2."""
    f = free_dofs(truss)
    K = stiffness(truss)[np.ix_(f, f)]
    M = mass_matrix(truss, model)[np.ix_(f, f)]
    L = np.linalg.cholesky(M)
    Linv = np.linalg.solve(L, np.eye(len(f)))
    A = Linv @ K @ Linv.T
    return np.linalg.eigvalsh(0.5 * (A + A.T))


def frequencies(truss, model="consistent"):
    """The natural frequencies [Hz] on the free dofs, ascending: sqrt(w^2) / (2 pi).

    A mechanism gives w^2 = 0 to round-off; a tiny negative round-off is read as 0."""
    w2 = eigenvalues(truss, model)
    return np.sqrt(np.clip(w2, 0.0, None)) / (2.0 * np.pi)
