#!/usr/bin/python3
"""Fit the Gauss-mollifier force curves (Pelteret & Reddy 2012, eq. 19-21) to standard
physiological curves: the `physiological` parameter set of materials/ContractileCurveSets.cpp.

Run with Debian's interpreter (numpy, scipy):  /usr/bin/python3 materials/fit/fit_physiological_curves.py
It prints the fitted parameters as C++ initialisers and the residuals recorded in doc/materials.md.
Deterministic: fixed starting points, no random numbers.

Term (eq. 21, closing factor as resolved in doc/materials.md):
    g(x) = A exp(-B |x - mu|^p) (R^q - |x - mu|^q)^s   for |x - mu| < R (0 outside), factor 1 if R = 0.

Targets
  f_cL(lambda_c): Gordon, Huxley & Julian (1966) frog sarcomere length-tension curve, piecewise
    linear through (1.27, 0), (1.67, 0.84), (2.00, 1), (2.25, 1), (3.65, 0) um, lengths divided by
    the plateau centre 2.125 um (so the optimum is lambda_c = 1); zero elsewhere in [0.5, 2].
    Constraints: f(1) = 1, f'(1) = 0, f <= 1, every term closes inside [0.5, 2] (so f_cL is
    continuous at the ends of eq. 19's domain).
  f_cV(v), v = d lambda_c / dt in 1/s:
    shortening (v <= 0): Hill (1938) hyperbola with a/T0 = 0.25 and v_max = 10:
        f = (1 + v/10) / (1 - v/2.5)          (f(0) = 1, f(-10) = 0)
    lengthening (v >= 0): van Soest & Bobbert (1993) eccentric hyperbola, asymptote 1.5, slope at
        v = 0 twice the concentric slope:  f = 1.5 - 0.25 / (v + 0.5)
    Constraints: f(0) = 1, f(10) = 1.5 and f'(10) = 0 (continuous, C1 join with eq. 20's constant
    1.5 above v = 10), f(-10) = 0 (one term closes exactly at -10, the others are < 1e-12 there).
"""
import numpy as np
from scipy.optimize import least_squares


def term(x, mu, p, A, B, R, q, s):
    d = np.abs(x - mu)
    g = A * np.exp(-B * d**p)
    if R > 0:
        g = np.where(d < R, g * np.clip(R**q - d**q, 0.0, None) ** s, 0.0)
    return g


def curve(x, terms):
    return sum(term(x, *t) for t in terms)


# ---------------------------------------------------------------- force-length
GHJ_UM = np.array([1.27, 1.67, 2.00, 2.25, 3.65])
GHJ_F = np.array([0.0, 0.84, 1.0, 1.0, 0.0])
OPTIMUM_UM = 2.125


def target_fl(lam):
    return np.interp(lam, GHJ_UM / OPTIMUM_UM, GHJ_F, left=0.0, right=0.0)


XL = np.linspace(0.5, 2.0, 601)


def fl_terms(z, shapes):
    terms = []
    for k, (p, q, s) in enumerate(shapes):
        mu, logA, logB, r = z[4 * k:4 * k + 4]
        room = min(mu - 0.5, 2.0 - mu)
        R = r * room
        # amplitudes are in units of the peak value of the closing factor, R^(q s)
        terms.append((mu, p, np.exp(logA) / R**(q * s), np.exp(logB), R, q, s))
    return terms


def fl_residual(z, shapes):
    terms = fl_terms(z, shapes)
    f = curve(XL, terms)
    h = 1e-6
    f1 = curve(np.array([1.0]), terms)[0]
    df1 = (curve(np.array([1.0 + h]), terms)[0] - curve(np.array([1.0 - h]), terms)[0]) / (2 * h)
    over = np.maximum(f - 1.0, 0.0)
    return np.concatenate([f - target_fl(XL), [30 * (f1 - 1.0), 100 * df1], 30 * over])


def fit_fl():
    best = None
    shapes_1 = [(p, q, s) for p in (2, 4) for q in (2, 4) for s in (2, 4)]
    for plateau in shapes_1:
        for flank in [(2, 2, 2), (2, 4, 4), (2, 2, 4)]:
            shapes = [flank, plateau, flank]
            # ascending flank, plateau, descending flank (the roles of Table II's three terms)
            start = [0.75, np.log(0.3), np.log(20), 0.9, 1.0, np.log(0.9), np.log(5), 0.9,
                     1.35, np.log(0.4), np.log(5), 0.9]
            lo = [0.55, -8, -3, 0.05] * 3
            hi = [1.95, 3, 8, 1.0] * 3
            sol = least_squares(fl_residual, start, args=(shapes,), bounds=(lo, hi), max_nfev=3000)
            if best is None or sol.cost < best[0].cost:
                best = (sol, shapes)
    sol, shapes = best
    terms = fl_terms(sol.x, shapes)
    scale = 1.0 / curve(np.array([1.0]), terms)[0]  # exact normalisation f(1) = 1
    return [(mu, p, A * scale, B, R, q, s) for (mu, p, A, B, R, q, s) in terms]


# ---------------------------------------------------------------- force-velocity
def target_fv(v):
    v = np.asarray(v, dtype=float)
    short = (1.0 + np.minimum(v, 0.0) / 10.0) / (1.0 - np.minimum(v, 0.0) / 2.5)
    return np.where(v <= 0.0, short, 1.5 - 0.25 / (np.maximum(v, 0.0) + 0.5))


XV = np.linspace(-10.0, 10.0, 801)
XV_FINE = np.linspace(-10.0, 10.0, 4001)


def fv_terms(z, shape):
    (q1, s1), inner = shape
    R1 = 20.0
    # g1: centred at v = 10, closing at v = -10; its peak value A1 R1^(q1 s1) is fixed to 1.5,
    # so f(10) = 1.5 exactly and f'(10) = 0 (C1 join with eq. 20's constant branch).
    terms = [(10.0, 2, 1.5 / R1**(q1 * s1), np.exp(z[0]), R1, q1, s1)]
    for k, (p, q, s) in enumerate(inner):
        mu, A, logB, r = z[1 + 4 * k:5 + 4 * k]
        R = r * min(mu + 10.0, 10.0 - mu)  # closes inside [-10, 10]
        terms.append((mu, p, A / R**(q * s), np.exp(logB), R, q, s))
    return terms


def fv_fix_origin(terms):
    """Adjust the amplitude of the last inner term so that f(0) = 1 exactly."""
    f0 = curve(np.array([0.0]), terms)[0]
    mu, p, A, B, R, q, s = terms[-1]
    shape0 = term(np.array([0.0]), mu, p, 1.0, B, R, q, s)[0]
    return terms[:-1] + [(mu, p, A + (1.0 - f0) / shape0, B, R, q, s)]


def fv_residual(z, shape):
    terms = fv_terms(z, shape)
    f = curve(XV, terms)
    # f_cV must rise strictly (a unique local solve): slope >= 1e-3 below v = 9, >= 0 above
    slope = np.diff(curve(XV_FINE, terms)) / np.diff(XV_FINE)
    decrease = np.minimum(slope - np.where(XV_FINE[1:] < 9.0, 1e-3, 0.0), 0.0)
    return np.concatenate([f - target_fv(XV), [30 * (curve(np.array([0.0]), terms)[0] - 1.0)],
                           1000 * decrease])


def fit_fv():
    best = None
    for q1, s1 in [(2, 1), (2, 2), (1, 2), (4, 1)]:
        for inner in [((2, 2, 2), (2, 2, 2)), ((2, 2, 4), (2, 2, 4)), ((2, 2, 2), (2, 2, 2), (2, 2, 2))]:
            shape = ((q1, s1), inner)
            n = len(inner)
            for mus in ([-3.0, 0.5, 0.0][:n], [-5.0, 2.0, -1.0][:n]):
                start = [np.log(0.01)]
                for mu in mus:
                    start += [mu, 0.2, np.log(0.1), 0.8]
                lo = [-12] + [-9.5, -5, -8, 0.05] * n
                hi = [2] + [9.5, 5, 4, 1.0] * n
                sol = least_squares(fv_residual, start, args=(shape,), bounds=(lo, hi), max_nfev=3000)
                if best is None or sol.cost < best[0].cost:
                    best = (sol, shape)
    sol, shape = best
    return fv_fix_origin(fv_terms(sol.x, shape))


def report(name, terms, xs, target):
    f = curve(xs, terms)
    err = f - target(xs)
    print(f"// {name}: RMS residual {np.sqrt(np.mean(err**2)):.4f}, max |residual| "
          f"{np.max(np.abs(err)):.4f} at x = {xs[np.argmax(np.abs(err))]:.3f}")
    for (mu, p, A, B, R, q, s) in terms:
        print(f"    {{{mu:.17g}, {p}, {A:.17g}, {B:.17g}, {R:.17g}, {q}, {s}}},")
    return f


if __name__ == "__main__":
    fl = fit_fl()
    f = report("f_cL (physiological)", fl, XL, target_fl)
    fine = np.linspace(0.5, 2.0, 150001)
    ff = curve(fine, fl)
    print(f"//   max {ff.max():.6f} at lambda_c = {fine[np.argmax(ff)]:.5f}; f(1) = {curve(np.array([1.0]), fl)[0]:.15f}")
    rising = np.all(np.diff(ff[fine <= 1.0]) >= 0.0) and np.all(np.diff(ff[fine >= 1.0]) <= 0.0)
    print(f"//   unimodal (rises to lambda_c = 1, falls after): {bool(rising)}")
    for x in (0.5, 0.6, 0.8, 0.9, 1.1, 1.2, 1.5, 1.7, 2.0):
        print(f"//   f_cL({x}) = {curve(np.array([x]), fl)[0]:.5f}  target {target_fl(x):.5f}")
    fv = fit_fv()
    report("f_cV (physiological)", fv, XV, target_fv)
    for x in (-10, -9.9, -5, -2, -1, 0, 0.5, 1, 2, 5, 9, 10):
        print(f"//   f_cV({x}) = {curve(np.array([float(x)]), fv)[0]:.6f}  target {float(target_fv(x)):.6f}")
    fine = np.linspace(-10, 10, 200001)
    d = np.diff(curve(fine, fv))
    print(f"//   f_cV monotone on [-10, 10]: {bool(np.all(d >= -1e-15))}; "
          f"max {curve(fine, fv).max():.6f}")
