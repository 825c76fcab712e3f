"""The paper's scene in GetFEM (python3-getfem, Debian's interpreter), for the work-precision
benchmark: the same discrete method as ContactBody's `standard` variant (consistent P1 mass,
midpoint rule, nodal contact and Coulomb friction on u^{k+1/2}, Rayleigh damping C = beta A),
built from GetFEM's own assembly and its basic contact brick (Alart-Curnier, Newton).

Writes an .npz with the output times, the displacement at every mesh node (i + j (nx+1)
order, as the FMU's field output) and the time spent in the step loop.

    /usr/bin/python3 benchmarks/getfem_scene.py NX DT STOP INTERVAL FRICTION BETA OUT.npz
"""
import sys
import time

import getfem as gf
import numpy as np

WIDTH = HEIGHT = 0.1
RHO, LAMBDA, MU = 1000.0, 300e6, 150e6
TOP, VELOCITY = -2.5e-5, 20.0


def main():
    nx, dt, stop, interval, friction, beta, out = (int(sys.argv[1]), *map(float, sys.argv[2:7]),
                                                   sys.argv[7])
    ny = nx
    mesh = gf.Mesh("regular simplices", np.linspace(0, WIDTH, nx + 1),
                   np.linspace(0, HEIGHT, ny + 1))
    mfu = gf.MeshFem(mesh, 2)
    mfu.set_classical_fem(1)
    mim = gf.MeshIm(mesh, 2)
    mesh.set_region(1, mesh.outer_faces_with_direction([0.0, 1.0], 0.01))

    # A and M from GetFEM's assembly.
    assembly = gf.Model("real")
    assembly.add_fem_variable("u", mfu)
    assembly.add_initialized_data("lambda", [LAMBDA])
    assembly.add_initialized_data("mu", [MU])
    assembly.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    assembly.assembly("build_matrix")
    A = assembly.tangent_matrix()
    M = gf.asm_mass_matrix(mim, mfu)
    M.scale(RHO)

    # Node numbering i + j (nx+1) from the dof coordinates (two dofs per node: x, y).
    dof_points = mfu.basic_dof_nodes()
    ndof = dof_points.shape[1]
    node = (np.rint(dof_points[0] / WIDTH * nx) + (nx + 1) * np.rint(dof_points[1] / HEIGHT * ny)
            ).astype(int)
    x_dofs = np.arange(0, ndof, 2)
    order = np.argsort(node[x_dofs])
    x_dofs = x_dofs[order]
    y_dofs = x_dofs + 1
    bottom = x_dofs[:nx + 1]

    nc = len(bottom)
    BN = gf.Spmat("empty", nc, ndof)
    BT = gf.Spmat("empty", nc, ndof)
    for i, dof in enumerate(bottom):
        BN[i, dof + 1] = -1.0  # B_N u <= gap: u_N = -u_y
        BT[i, dof] = 1.0

    c1, c2 = 4.0 / dt**2, 2.0 / dt
    K = gf.Spmat("copy", M)
    K.scale(c1)
    scaled_A = gf.Spmat("copy", A)
    scaled_A.scale(1.0 + c2 * beta)
    K = gf.Spmat("add", K, scaled_A)

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_explicit_matrix("u", "u", K)
    rhs_brick = md.add_explicit_rhs("u", np.zeros(ndof))
    md.add_initialized_data("top", [0.0, TOP])
    md.add_Dirichlet_condition_with_simplification("u", 1, "top")
    md.add_variable("lambda_n", nc)
    # Augmentation of the order of K's diagonal (Alart-Curnier converges for any r > 0).
    md.add_initialized_data("r", [float(np.mean([K[i, i] for i in bottom]))])
    md.add_initialized_data("gap", np.zeros(nc))
    if friction > 0:
        md.add_variable("lambda_t", nc)
        md.add_initialized_data("friction", [friction])
        md.add_initialized_data("alpha", [c2])
        # GetFEM 5.4's basic brick slides on alpha (B_T u + gamma B_T wt): the midpoint slip
        # (2/dt)(u_x^{k+1/2} - u_x^k) - V with wt = -(u_x^k + dt V / 2) (checked against the
        # FMU's standard variant, which it matches to round-off).
        md.add_initialized_data("gamma", [1.0])
        md.add_initialized_data("wt", np.zeros(ndof))
        md.add_basic_contact_brick("u", "lambda_n", "lambda_t", "r", BN, BT, "friction",
                                   "gap", "alpha", 1, "gamma", "wt")
    else:
        md.add_basic_contact_brick("u", "lambda_n", "r", BN, "gap")

    # The paper's initial state: u_y = top * y / H, v = 0.
    u = np.zeros(ndof)
    u[1::2] = TOP * dof_points[1, 1::2] / HEIGHT
    v = np.zeros(ndof)
    steps_per_output = round(interval / dt)
    outputs = round(stop / interval)
    times, fields = [0.0], [np.stack([u[x_dofs], u[y_dofs]], axis=1)]
    start = time.perf_counter()
    for k in range(outputs * steps_per_output):
        rhs = np.asarray(M.mult(c1 * u + c2 * v)).ravel()
        if beta > 0:
            rhs += c2 * beta * np.asarray(A.mult(u)).ravel()
        md.set_private_rhs(rhs_brick, rhs)
        if friction > 0:
            wt = np.zeros(ndof)
            wt[bottom] = -(u[bottom] + 0.5 * dt * VELOCITY)
            md.set_variable("wt", wt)
        # The residual is a force: relative to the right-hand side's size, as the FMU's is.
        # GetFEM's default line search stalls on the friction steps; the plain one does not.
        iterations, converged = md.solve("max_res", 1e-11 * np.abs(rhs).max(), "max_iter", 100,
                                         "lsearch", "simplest")
        if not converged:
            sys.exit(f"GetFEM Newton did not converge at substep {k} ({iterations} iterations)")
        u_half = md.variable("u")
        v = 4.0 / dt * (u_half - u) - v
        u = 2.0 * u_half - u
        if (k + 1) % steps_per_output == 0:
            times.append((k + 1) * dt)
            fields.append(np.stack([u[x_dofs], u[y_dofs]], axis=1))
    wall = time.perf_counter() - start
    np.savez(out, times=np.array(times), displacement=np.array(fields), wall=wall,
             substeps=outputs * steps_per_output)


if __name__ == "__main__":
    main()
