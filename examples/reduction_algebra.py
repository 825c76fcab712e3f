"""The algebra of the reduced body (the construction in docs/decisions.md), checked on a
random symmetric stiffness A and a mass M with massless rows (the paper's M_r) before any of
it is built into the solver: numpy only, 1 s.

Construction: the m lowest modes Phi of A phi = w^2 M phi (mass-normalized), the residual
flexibility R = A^-1 - Phi W^-2 Phi^T, the residual attachment modes Psi = R B^T of the contact
dofs, kept where G = B R B^T has rank and scaled to Psi' = Psi V g^-1/2, T = [Phi, Psi'].
Claims printed (each could come out otherwise):
  - T^T A T = diag(W^2, I)                     (the stiffness is diagonal);
  - Phi^T M Psi' = 0                           (no mass coupling between modes and residual);
  - T (T^T A T)^-1 T^T B^T = A^-1 B^T          (the edge's static response is exact, any m);
  - with every finite mode: T is square and of full rank, Psi'^T M Psi' = 0, so the reduced
    model with a massless residual is the full model in other coordinates.

    .venv/bin/python examples/reduction_algebra.py
"""
import numpy as np


def generalized_modes(A, M):
    """Finite modes of A phi = w^2 M phi for A SPD and M PSD: (w^2 ascending, Phi with
    Phi^T M Phi = I)."""
    L = np.linalg.cholesky(A)
    Li = np.linalg.inv(L)
    mu, Y = np.linalg.eigh(Li @ M @ Li.T)   # M v = mu A v, mu = 1 / w^2
    finite = mu > 1e-12 * mu.max()
    U = Li.T @ Y[:, finite]                  # U^T A U = I
    w2 = 1 / mu[finite]
    order = np.argsort(w2)
    return w2[order], (U / np.sqrt(mu[finite]))[:, order]


def reduce(A, M, B, m):
    w2, Phi = generalized_modes(A, M)
    P, W2 = Phi[:, :m], w2[:m]
    R = np.linalg.inv(A) - P @ np.diag(1 / W2) @ P.T
    G = B @ R @ B.T
    g, V = np.linalg.eigh(G)
    kept = g > 1e-12 * max(g.max(), 1e-300)
    Psi = R @ B.T @ V[:, kept] / np.sqrt(g[kept])
    return np.hstack([P, Psi]), W2, int(kept.sum()), len(w2)


def main():
    rng = np.random.default_rng(1)
    n = 40
    massless = [0, 2, 4, 6, 8]                               # normal contact dofs
    contact = sorted(massless + [1, 3, 5, 7, 9])            # with the tangential ones
    X = rng.standard_normal((n, n))
    A = X @ X.T + n * np.eye(n)
    Y = rng.standard_normal((n, n))
    M = Y @ Y.T + np.eye(n)
    M[massless, :] = 0
    M[:, massless] = 0
    B = np.eye(n)[contact]
    exact_static = np.linalg.solve(A, B.T)
    for m in (3, 10, None):
        T, W2, k, finite = reduce(A, M, B, m if m else n)
        m = len(W2)
        Ah, Mh = T.T @ A @ T, T.T @ M @ T
        print(f"m = {m:2d} of {finite} finite modes: residual columns {k}, rank T {np.linalg.matrix_rank(T)} of {n}; "
              f"|T'AT - diag| {np.abs(Ah - np.diag(np.r_[W2, np.ones(k)])).max():.1e}, "
              f"|Phi'M Psi| {np.abs(Mh[:m, m:]).max():.1e}, |Psi'M Psi| {np.abs(Mh[m:, m:]).max():.1e}, "
              f"static error {np.abs(T @ np.linalg.solve(Ah, T.T @ B.T) - exact_static).max() / np.abs(exact_static).max():.1e}")


if __name__ == "__main__":
    main()
