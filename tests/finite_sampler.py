"""An independent numerical sampler of a closed system's configuration space.

Written apart from :mod:`coopkin_sym.analysis.finite`: the loop closure in the world
frame (``c_link(q) = R c0 + p``, and ``R_link(q) R_link(q0)^T = R`` for a welded
contact), the joints by Rodrigues' formula, the object by the exponential map, all in
mpmath at 60 digits. Random small displacements of every coordinate are projected
onto the closure by Gauss-Newton; the projected points show the local dimension (the
largest dimension of the closure at them, from the cloud of points projected from
around each, away from the point itself) and the directions of the branches
(``(point - q0) / |point - q0|``).

Example
-------
>>> from coopkin_sym import load
>>> s = Sampler(load("paper-case1-planar").model, {"q1": 0, "q2": 0}, {"L": 1})
>>> s.dimension(samples=6)
1
"""

from __future__ import annotations

import random

import mpmath as mp

mp.mp.dps = 60

STEP = mp.mpf(10) ** -25       # of the difference quotients
RADIUS = mp.mpf(10) ** -3     # of the random displacements
TOLERANCE = mp.mpf(10) ** -12  # of the numerical rank


def _rot(axis, angle):
    """Rodrigues: the rotation by ``angle`` about the unit ``axis``."""
    k = mp.matrix([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return mp.eye(3) + mp.sin(angle) * k + (1 - mp.cos(angle)) * k * k


def _exp_rot(phi):
    theta = mp.sqrt(sum(x * x for x in phi))
    if theta == 0:
        return mp.eye(3)
    return _rot([x / theta for x in phi], theta)


class Sampler:
    """Points of the closure of ``model`` (hard, complete and frictionless contacts: a
    frictionless one keeps the link's point on the object's face through it) near the joint
    values ``q0`` (radians; the object's place follows from them), the parameters at
    ``params``."""

    def __init__(self, model, q0: dict, params: dict):
        import sympy as sp

        def num(x):
            x = sp.sympify(x)
            x = x.subs({s: params[s.name] for s in x.free_symbols})
            return mp.mpf(sp.Rational(x).p) / sp.Rational(x).q
        self.model = model
        self.planar = model.planar
        self.joints = []
        for arm in model.arms:
            self.joints.append([(j.name, j.type, [num(x) for x in j.axis],
                                 None if j.point is None else [num(x) for x in j.point])
                                for j in arm.joints])
        self.contacts = [(c.arm, c.link, [num(x) for x in c.point], c.model)
                         for c in model.contacts]
        # a frictionless contact's normal, in its link's frame at q = 0
        self.normals = [None if c.normal is None else [num(x) for x in c.normal]
                        for c in model.contacts]
        self.names = [j[0] for arm in self.joints for j in arm
                      if j[0] not in model.locked]
        self.q0 = {name: mp.mpf(q0.get(name, 0)) for arm in self.joints for name, *_ in arm}
        self.nobj = 3 if self.planar else 6
        self.n = self.nobj + len(self.names)
        self.home = {}
        self.faces = {}
        for i, (arm, link, point, _) in enumerate(self.contacts):
            self.home[i] = self._link(arm, link, self.q0, point)
            if self.normals[i] is not None:       # the face's normal at q0, in the world
                self.faces[i] = self.home[i][0] * mp.matrix(self.normals[i])

    def _link(self, arm, link, q, point):
        """The pose (R, t) of the link and the world position of ``point`` on it."""
        rot, trans = mp.eye(3), mp.matrix([0, 0, 0])
        if arm is None:
            return rot, mp.matrix(point)
        for name, kind, axis, origin in self.joints[arm][:link]:
            if kind == "revolute":
                turn = _rot(axis, q[name])
                o = mp.matrix(origin)
                rot, trans = rot * turn, rot * (o - turn * o) + trans
            else:
                trans = trans + rot * mp.matrix(axis) * q[name]
        return rot, rot * mp.matrix(point) + trans

    def closure(self, x):
        """The loop-closure residuals at ``x = (object displacement, joint changes)``."""
        if self.planar:
            p, phi = mp.matrix([x[0], x[1], 0]), [0, 0, x[2]]
        else:
            p, phi = mp.matrix(x[0:3]), list(x[3:6])
        r = _exp_rot(phi)
        q = dict(self.q0)
        for k, name in enumerate(self.names):
            q[name] = self.q0[name] + x[self.nobj + k]
        out = []
        for i, (arm, link, point, model_) in enumerate(self.contacts):
            rot0, c0 = self.home[i]
            rot, c = self._link(arm, link, q, point)
            gap = c - (r * c0 + p)
            if model_ == "frictionless":         # the point stays on the object's face
                normal = r * self.faces[i]
                out.append(sum(normal[k] * gap[k] for k in range(3)))
                continue
            out += [gap[0], gap[1]] + ([] if self.planar else [gap[2]])
            if model_ == "complete":
                m = rot * rot0.T - r
                out += [m[1, 0]] if self.planar else [m[2, 1], m[0, 2], m[1, 0]]
        return out

    def jacobian(self, x, h=STEP):
        f0 = self.closure(x)
        cols = []
        for k in range(self.n):
            y = list(x)
            y[k] += h
            cols.append([(a - b) / h for a, b in zip(self.closure(y), f0, strict=True)])
        return mp.matrix([[cols[k][i] for k in range(self.n)] for i in range(len(f0))])

    def project(self, x, steps: int = 40):
        """Gauss-Newton from ``x`` onto the closure; ``None`` when it does not get
        there. Plain least-norm steps first; where they fail (``J J^T`` numerically
        singular, or no convergence within ``steps``), again with the truncated steps of
        :meth:`_truncated_step`, each at most ``RADIUS`` long."""
        return self._newton(x, steps, robust=False) or self._newton(x, steps, robust=True)

    def _newton(self, x, steps, robust):
        x = list(x)
        for _ in range(steps):
            f = mp.matrix(self.closure(x))
            if mp.norm(f) < mp.mpf(10) ** -40:
                return x
            j = self.jacobian(x)
            if robust:
                dx = self._truncated_step(j, f)
                length = mp.sqrt(sum(v * v for v in dx))
                if length > RADIUS:  # a trust region: no jump along a nearly free direction
                    dx = [v * RADIUS / length for v in dx]
            else:
                try:
                    step = mp.lu_solve(j * j.T + mp.eye(j.rows) * mp.mpf(10) ** -45, f)
                except ZeroDivisionError:  # numerically singular
                    return None
                dx = j.T * step
            x = [x[k] - dx[k] for k in range(self.n)]
        return x if mp.norm(mp.matrix(self.closure(x))) < mp.mpf(10) ** -30 else None

    @staticmethod
    def _truncated_step(j, f):
        """The least-norm solution of ``J dx = f`` by the singular value decomposition,
        singular values below ``10^-6`` of the largest dropped: a direction along
        which the closure is nearly free (a tangent of the closure, slightly off it)
        is not a direction to correct along, and a row of zeros (a folded
        configuration) leaves no normal equations to solve."""
        u, s, v = mp.svd_r(j)
        top = max((abs(x) for x in s), default=0)
        dx = [mp.mpf(0)] * j.cols
        for k in range(len(s)):
            if top == 0 or abs(s[k]) <= top * mp.mpf(10) ** -6:
                continue
            coefficient = sum(u[i, k] * f[i] for i in range(j.rows)) / s[k]
            for c in range(j.cols):
                dx[c] += coefficient * v[k, c]
        return dx

    def points(self, samples: int = 12, radius=RADIUS, seed: int = 1):
        rng = random.Random(seed)
        found = []
        for _ in range(samples):
            x = [radius * mp.mpf(rng.uniform(-1, 1)) for _ in range(self.n)]
            y = self.project(x)
            if y is not None:
                found.append(y)
        return found

    def rank(self, x, tol=TOLERANCE) -> int:
        s = mp.svd_r(self.jacobian(x), compute_uv=False)
        return sum(1 for v in s if abs(v) > tol)

    def local_dimension(self, x, seed: int = 2) -> int:
        """The dimension of the closure at its point ``x``, from a cloud around it:
        small displacements projected back, and the count of the cloud's singular
        values above a hundredth of the largest (its tangent space)."""
        rng = random.Random(seed)
        size = mp.sqrt(sum(v * v for v in x)) / 1000
        cloud = []
        for _ in range(self.n + 3):
            y = self.project([v + size * mp.mpf(rng.uniform(-1, 1)) for v in x])
            if y is not None:
                cloud.append([a - b for a, b in zip(y, x, strict=True)])
        if not cloud:
            return 0
        s = mp.svd_r(mp.matrix(cloud), compute_uv=False)
        top = max(abs(v) for v in s)
        return sum(1 for v in s if abs(v) > top / 100) if top > 0 else 0

    def dimension(self, samples: int = 12, radius=RADIUS) -> int:
        """The largest dimension of the closure at the projected points that stay
        away from the configuration (0 when every projection falls back onto it: it
        is isolated)."""
        away = [x for x in self.points(samples, radius)
                if mp.sqrt(sum(v * v for v in x)) > radius / 100]
        return max((self.local_dimension(x) for x in away), default=0)

    def directions(self, samples: int = 12, radius=RADIUS):
        """Unit vectors from the configuration to the projected points away from it."""
        out = []
        for x in self.points(samples, radius):
            norm = mp.sqrt(sum(v * v for v in x))
            if norm > radius / 100:
                out.append([v / norm for v in x])
        return out
