"""Reading the FMU's field output (.pvd + .vtu through meshio) and P1 quantities on it:
energies, and L2 / H1 norms of the difference of two fields on nested structured meshes.

Everything is computed triangle by triangle with numpy (no sparse matrices needed)."""
import pathlib
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def read_collection(pvd):
    """[(time, path of the .vtu)] listed by a .pvd collection, in time order."""
    pvd = pathlib.Path(pvd)
    root = ET.parse(pvd).getroot()
    items = [(float(d.get("timestep")), pvd.parent / d.get("file")) for d in root.iter("DataSet")]
    return sorted(items)


def read_field(vtu):
    """(points[:, :2], triangles, point_data) of one snapshot."""
    mesh = meshio.read(vtu)
    data = {k: v[:, 0] if v.ndim == 2 and v.shape[1] == 1 else v for k, v in mesh.point_data.items()}
    return mesh.points[:, :2], mesh.cells_dict["triangle"], data


def _geometry(points, triangles):
    p = points[triangles]                      # (T, 3, 2)
    d1, d2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    det = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    area = 0.5 * np.abs(det)
    # Gradients of the three barycentric functions, constant per triangle: (T, 3, 2).
    grad = np.empty((len(triangles), 3, 2))
    grad[:, 1] = np.stack([d2[:, 1], -d2[:, 0]], axis=1) / det[:, None]
    grad[:, 2] = np.stack([-d1[:, 1], d1[:, 0]], axis=1) / det[:, None]
    grad[:, 0] = -grad[:, 1] - grad[:, 2]
    return area, grad


def l2_squared(points, triangles, values):
    """Integral of |e|^2 for a P1 field e given at the nodes (scalar or vector rows)."""
    area, _ = _geometry(points, triangles)
    v = values[triangles]                      # (T, 3[, c])
    local = (v ** 2).sum(axis=1) + v.sum(axis=1) ** 2
    if local.ndim > 1:
        local = local.sum(axis=1)
    return float((area / 12 * local).sum())


def h1_squared(points, triangles, values):
    """Integral of |grad e|^2 (the H1 seminorm squared) for a P1 vector field e."""
    area, grad = _geometry(points, triangles)
    g = np.einsum("tkd,tkc->tcd", grad, values[triangles])  # (T, c, 2)
    return float((area * (g ** 2).sum(axis=(1, 2))).sum())


def strain_energy(points, triangles, u, lam, mu):
    """1/2 u^T A u for plane-strain linear elasticity with Lame coefficients lam, mu."""
    area, grad = _geometry(points, triangles)
    g = np.einsum("tkd,tkc->tcd", grad, u[triangles, :2])  # g[t, c, d] = d u_c / d x_d
    eps = 0.5 * (g + g.transpose(0, 2, 1))
    trace = eps[:, 0, 0] + eps[:, 1, 1]
    density = 0.5 * lam * trace ** 2 + mu * (eps ** 2).sum(axis=(1, 2))
    return float((area * density).sum())


def von_mises(points, triangles, u, lam, mu):
    """The von Mises stress of each triangle (Pa), plane strain (sigma_zz = lam tr eps)."""
    _, grad = _geometry(points, triangles)
    g = np.einsum("tkd,tkc->tcd", grad, u[triangles, :2])
    eps = 0.5 * (g + g.transpose(0, 2, 1))
    trace = eps[:, 0, 0] + eps[:, 1, 1]
    sxx = lam * trace + 2 * mu * eps[:, 0, 0]
    syy = lam * trace + 2 * mu * eps[:, 1, 1]
    sxy = 2 * mu * eps[:, 0, 1]
    szz = lam * trace
    return np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy ** 2)


def read_solid_field(vtu):
    """(points (N, 3), tetrahedra (T, 4), point_data) of one 3D snapshot."""
    mesh = meshio.read(vtu)
    return mesh.points, mesh.cells_dict["tetra"], dict(mesh.point_data)


def von_mises_solid(points, tetrahedra, u, lam, mu):
    """The von Mises stress of each P1 tetrahedron (Pa): its constant strain from the shape
    gradients, sigma = lam tr(eps) I + 2 mu eps."""
    p = points[tetrahedra]                              # (T, 4, 3)
    edges = (p[:, 1:] - p[:, :1]).transpose(0, 2, 1)    # (T, 3, 3): columns p_k - p_0
    du = (u[tetrahedra[:, 1:]] - u[tetrahedra[:, :1]]).transpose(0, 2, 1)  # (T, 3, 3)
    g = du @ np.linalg.inv(edges)                       # grad u
    eps = 0.5 * (g + g.transpose(0, 2, 1))
    trace = np.trace(eps, axis1=1, axis2=2)
    sigma = 2 * mu * eps + lam * trace[:, None, None] * np.eye(3)
    deviator = sigma - np.trace(sigma, axis1=1, axis2=2)[:, None, None] / 3 * np.eye(3)
    return np.sqrt(1.5 * np.einsum("tij,tij->t", deviator, deviator))


def boundary_faces(tetrahedra):
    """(faces (F, 3), the tetrahedron of each): the triangles that belong to one tetrahedron."""
    faces = np.concatenate([tetrahedra[:, [1, 2, 3]], tetrahedra[:, [0, 3, 2]],
                            tetrahedra[:, [0, 1, 3]], tetrahedra[:, [0, 2, 1]]])
    owner = np.tile(np.arange(len(tetrahedra)), 4)
    _, index, counts = np.unique(np.sort(faces, axis=1), axis=0, return_index=True, return_counts=True)
    once = index[counts == 1]
    return faces[once], owner[once]


def kinetic_energy(points, triangles, v, density):
    """1/2 v^T M v with the consistent P1 mass matrix."""
    return 0.5 * density * l2_squared(points, triangles, v[:, :2])


def interpolate_nested(coarse_points, coarse_values, nx, ny, width, height, fine_points):
    """Evaluates a P1 field of the structured nx x ny mesh (its diagonals: solver/mesh/mesh.hpp) at the fine
    mesh's nodes. On nested meshes the result is the same field, exactly, as a fine P1 field."""
    hx, hy = width / nx, height / ny
    x, y = fine_points[:, 0] / hx, fine_points[:, 1] / hy
    i = np.clip(np.floor(x + 1e-9).astype(int), 0, nx - 1)
    j = np.clip(np.floor(y + 1e-9).astype(int), 0, ny - 1)
    xi, eta = x - i, y - j
    node = lambda a, b: (j + b) * (nx + 1) + (i + a)  # noqa: E731
    f = coarse_values
    v00, v10, v01, v11 = f[node(0, 0)], f[node(1, 0)], f[node(0, 1)], f[node(1, 1)]
    w = lambda a: a[:, None] if f.ndim > 1 else a  # noqa: E731
    even = (i + j) % 2 == 0
    # Even cells: diagonal (0,0)-(1,1); odd cells: diagonal (1,0)-(0,1).
    lower = xi >= eta
    even_val = np.where(w(lower),
                        w(1 - xi) * v00 + w(xi - eta) * v10 + w(eta) * v11,
                        w(1 - eta) * v00 + w(xi) * v11 + w(eta - xi) * v01)
    below = xi + eta <= 1
    odd_val = np.where(w(below),
                       w(1 - xi - eta) * v00 + w(xi) * v10 + w(eta) * v01,
                       w(xi + eta - 1) * v11 + w(1 - eta) * v10 + w(1 - xi) * v01)
    return np.where(w(even), even_val, odd_val)
