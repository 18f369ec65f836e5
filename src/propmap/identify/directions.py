"""The directions a fit's data determine against the population prior.

A static thrust-stand run determines only a few combinations of the cambered section's
parameters (a thrust level, a power level and their rpm trend: 3.7-3.9 effective parameters
on UIUC static runs, docs/identification.md). Fitting all eight under the population prior
moves every combination by what data and prior together allow; fitting only the data's K
leading directions, and holding the others at the prior mean, frees what the data
determine and nothing else. The directions are the eigenvectors of the data's information
in the prior's whitened coordinates z = L^-1 (x - mu) (Sigma = L L^T the population
covariance): (J L)^T (J L) / w^2 u = lambda u, J the data residuals' Jacobian at the prior
mean and w the prior rows' weight; lambda is how much more the data know along u than the
prior does. Keeping the K largest is principal-components regression in the prior's metric
(T. Hastie, R. Tibshirani and J. Friedman, The Elements of Statistical Learning, 2nd ed.,
2009, Sec. 3.5.1; ridge regression, the full fit under the prior, shrinks along the same
directions by lambda / (1 + lambda) instead, Sec. 3.4.1 eq 3.47).
"""

from __future__ import annotations

import numpy as np

__all__ = ["DATA_OVER_PRIOR", "STATIC_DIRECTIONS", "leading_directions"]

#: directions a static run's fit frees by default (FitOptions.directions; the measurement
#: behind it is in docs/identification.md)
STATIC_DIRECTIONS = 3
#: with sweeps at one rotation rate a fit frees the directions along which the data
#: know at least this many times more than the prior (eigenvalue lambda >= 10: the posterior
#: standard deviation there at most 1/sqrt(11) of the prior's; docs/identification.md)
DATA_OVER_PRIOR = 10.0


def leading_directions(jac: np.ndarray, chol: np.ndarray, weight: float, k: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``k`` parameter directions the data determine best against a Gaussian prior.

    Parameters
    ----------
    jac : ndarray, shape (N, p)
        The data residuals' Jacobian with respect to the p parameters at the prior mean.
    chol : ndarray, shape (p, p)
        Lower Cholesky factor L of the prior covariance, Sigma = L L^T.
    weight : float
        Weight w of the prior's pseudo-residuals w L^-1 (x - mu) in the residuals' unit.
    k : int
        Number of directions, 1 <= k <= p.

    Returns
    -------
    B : ndarray, shape (p, k)
        Columns L u_i: the parameter change of one prior standard deviation along each
        direction, the directions ordered by decreasing eigenvalue; each u_i's largest
        component is positive (a reproducible sign).
    eigenvalues : ndarray, shape (p,)
        lambda_i of (J L)^T (J L) / w^2, decreasing: the data's information over the
        prior's along each direction (all p, for the report).

    Raises
    ------
    ValueError
        ``k`` outside [1, p], or shapes that do not match.
    """
    jac, chol = np.asarray(jac, float), np.asarray(chol, float)
    p = chol.shape[0]
    if jac.ndim != 2 or jac.shape[1] != p or chol.shape != (p, p):
        raise ValueError(f"jac must have shape (N, {p}) and chol ({p}, {p}), got {jac.shape} and {chol.shape}")
    if not 1 <= k <= p:
        raise ValueError(f"k must be in [1, {p}], got {k}")
    jz = jac @ chol
    lam, U = np.linalg.eigh(jz.T @ jz / weight**2)
    order = np.argsort(lam)[::-1]
    lam, U = lam[order], U[:, order]
    U = U * np.where(U[np.argmax(np.abs(U), axis=0), np.arange(p)] < 0, -1.0, 1.0)
    return chol @ U[:, :k], lam
