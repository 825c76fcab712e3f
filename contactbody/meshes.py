"""Gmsh meshes for ContactBody's `mesh` parameter, written by the real Gmsh (the `gmsh` wheel,
its Python API): the shapes the tests, the Hertz benchmark and the examples use. Each file
holds first-order triangles in the x-y plane and the physical line groups "contact" and
"clamp" that the FMU reads (docs/contract.md, "A mesh from Gmsh").

    from contactbody import meshes
    meshes.half_disk("roller.msh", radius=0.05, contact_size=5e-4, far_size=5e-3)

Gmsh is only the writer: the FMU reads the MSH format itself and links no Gmsh.
"""
import contextlib
import math
import pathlib

VERSIONS = {"4.1": 4.1, "2.2": 2.2}


@contextlib.contextmanager
def session(name):
    """One Gmsh model, quiet, finalized whatever happens."""
    import gmsh
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add(name)
        yield gmsh
    finally:
        gmsh.finalize()


def write(gmsh, path, version="4.1", binary=False):
    gmsh.option.setNumber("Mesh.MshFileVersion", VERSIONS[version])
    gmsh.option.setNumber("Mesh.Binary", int(binary))
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    gmsh.write(str(path))
    return path


def rectangle(path, width=0.1, height=0.1, nx=20, ny=20, shift=(0.0, 0.0), version="4.1",
              clamp_right=False):
    """The FMU's own rectangle (solver/mesh/mesh.cpp: nodes numbered row by row from the bottom,
    cells split as GetFEM's regular simplices), moved by `shift`, as a Gmsh file: bottom edge
    "contact", top edge "clamp". Given to `mesh`, it is the body of mesh = "" (shift (0, 0)).
    `clamp_right`: the right edge is the clamp's too (a clamp that spans several heights)."""
    node = lambda i, j: j * (nx + 1) + i + 1  # Gmsh tags from 1
    coords, tris = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            coords += [shift[0] + i * width / nx, shift[1] + j * height / ny, 0.0]
    for j in range(ny):
        for i in range(nx):
            n00, n10, n01, n11 = node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)
            tris += [n00, n10, n11, n00, n11, n01] if (i + j) % 2 == 0 else [n00, n10, n01, n10, n11, n01]
    lines = lambda j: [t for i in range(nx) for t in (node(i, j), node(i + 1, j))]
    right = [t for j in range(ny) for t in (node(nx, j), node(nx, j + 1))] if clamp_right else []
    with session("rectangle") as gmsh:
        discrete_mesh(gmsh, coords, tris, {"contact": lines(0), "clamp": lines(ny) + right})
        return write(gmsh, path, version)


def discrete_mesh(gmsh, coords, triangles, groups, surface_group="body"):
    """Nodes (x, y, z flat, tags from 1), triangles (node tags, three each) and line groups
    {name: node tags, two per line} as Gmsh discrete entities with physical groups."""
    surface = gmsh.model.addDiscreteEntity(2)
    n = len(coords) // 3
    gmsh.model.mesh.addNodes(2, surface, list(range(1, n + 1)), coords)
    gmsh.model.mesh.addElementsByType(surface, 2, [], triangles)
    gmsh.model.addPhysicalGroup(2, [surface], name=surface_group)
    for name, nodes in groups.items():
        curve = gmsh.model.addDiscreteEntity(1)
        gmsh.model.mesh.addElementsByType(curve, 1, [], nodes)
        gmsh.model.addPhysicalGroup(1, [curve], name=name)


def _refine_near(gmsh, point, fine, coarse, distance, fine_distance=None, entities="PointsList"):
    """Element size `fine` within `fine_distance` (by default `distance`/10) of `point` (a
    point's tag, or a list of the tags `entities` names: "SurfacesList", ...), growing to
    `coarse` at `distance`."""
    field = gmsh.model.mesh.field
    d = field.add("Distance")
    field.setNumbers(d, entities, point if isinstance(point, list) else [point])
    t = field.add("Threshold")
    field.setNumber(t, "InField", d)
    field.setNumber(t, "SizeMin", fine)
    field.setNumber(t, "SizeMax", coarse)
    field.setNumber(t, "DistMin", fine_distance if fine_distance is not None else distance / 10)
    field.setNumber(t, "DistMax", distance)
    field.setAsBackgroundMesh(t)
    for option in ("Mesh.MeshSizeExtendFromBoundary", "Mesh.MeshSizeFromPoints", "Mesh.MeshSizeFromCurvature"):
        gmsh.option.setNumber(option, 0)


def half_disk(path, radius=0.05, contact_size=5e-4, far_size=5e-3, refine_distance=None,
              fine_distance=None, contact_angle=180.0, version="4.1"):
    """A half-cylinder's cross-section: its flat face on top (y = radius, "clamp"), its arc
    below touching y = 0 at x = 0; the arc within `contact_angle` degrees around the bottom is
    "contact". Elements of `contact_size` within `fine_distance` of the bottom point (by
    default a tenth of `refine_distance`), `far_size` beyond `refine_distance` (by default
    radius / 2)."""
    r = radius
    with session("half_disk") as gmsh:
        geo = gmsh.model.geo
        c = geo.addPoint(0, r, 0)
        left, right, bottom = geo.addPoint(-r, r, 0), geo.addPoint(r, r, 0), geo.addPoint(0, 0, 0)
        half = math.radians(contact_angle) / 2
        arcs = []
        if contact_angle < 180:
            a = geo.addPoint(-r * math.sin(half), r - r * math.cos(half), 0)
            b = geo.addPoint(r * math.sin(half), r - r * math.cos(half), 0)
            free_left, contact_left = geo.addCircleArc(left, c, a), geo.addCircleArc(a, c, bottom)
            contact_right, free_right = geo.addCircleArc(bottom, c, b), geo.addCircleArc(b, c, right)
            arcs = [free_left, contact_left, contact_right, free_right]
            contact = [contact_left, contact_right]
        else:
            arcs = [geo.addCircleArc(left, c, bottom), geo.addCircleArc(bottom, c, right)]
            contact = arcs
        top = geo.addLine(right, left)
        loop = geo.addCurveLoop(arcs + [top])
        surface = geo.addPlaneSurface([loop])
        geo.synchronize()
        gmsh.model.addPhysicalGroup(2, [surface], name="body")
        gmsh.model.addPhysicalGroup(1, contact, name="contact")
        gmsh.model.addPhysicalGroup(1, [top], name="clamp")
        _refine_near(gmsh, bottom, contact_size, far_size, refine_distance or r / 2, fine_distance)
        gmsh.model.mesh.generate(2)
        return write(gmsh, path, version)


def block(path, size=0.1, cells=6, version="4.1"):
    """A 3D cube of edge `size`, [0, size]^3, each of its cells^3 cubes split into Kuhn's six
    tetrahedra (conforming across faces), written by Gmsh: bottom face (y = 0) "contact", top
    face (y = size) "clamp". ContactBody3D's default body (resources/block.msh) is block() with
    the defaults."""
    n = cells
    node = lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)  # Gmsh tags from 1
    h = size / n
    coords = []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                coords += [i * h, j * h, k * h]
    point = lambda t: coords[3 * (t - 1): 3 * t]
    tets = []
    paths = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for axes in paths:  # the six paths from corner 000 to 111, one axis at a time
                    at = [i, j, k]
                    tet = [node(*at)]
                    for axis in axes:
                        at[axis] += 1
                        tet.append(node(*at))
                    p0, p1, p2, p3 = (point(t) for t in tet)
                    a, b, c = ([q[d] - p0[d] for d in range(3)] for q in (p1, p2, p3))
                    det = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                           + a[2] * (b[0] * c[1] - b[1] * c[0]))
                    if det < 0:
                        tet[1], tet[2] = tet[2], tet[1]
                    tets += tet
    # A face's triangles split it along the diagonal from its least to its greatest corner, as
    # the tetrahedra do.
    face = lambda j: [t for i in range(n) for k in range(n) for t in (
        node(i, j, k), node(i + 1, j, k), node(i + 1, j, k + 1),
        node(i, j, k), node(i + 1, j, k + 1), node(i, j, k + 1))]
    with session("block") as gmsh:
        volume = gmsh.model.addDiscreteEntity(3)
        gmsh.model.mesh.addNodes(3, volume, list(range(1, len(coords) // 3 + 1)), coords)
        gmsh.model.mesh.addElementsByType(volume, 4, [], tets)
        gmsh.model.addPhysicalGroup(3, [volume], name="body")
        for name, j in (("contact", 0), ("clamp", n)):
            surface = gmsh.model.addDiscreteEntity(2)
            gmsh.model.mesh.addElementsByType(surface, 2, [], face(j))
            gmsh.model.addPhysicalGroup(2, [surface], name=name)
        return write(gmsh, path, version)


def hemisphere(path, radius=0.05, contact_size=1e-3, far_size=1e-2, refine_distance=None,
               fine_distance=None, contact_angle=60.0, version="4.1"):
    """A 3D body of tetrahedra: the lower half of a ball of `radius` centred at (0, radius, 0),
    its flat face on top (y = radius, "clamp"), its curved face touching y = 0 at the origin.
    The cap of the curved face within `contact_angle` degrees around the bottom is "contact"
    (surface triangles). Elements of `contact_size` within `fine_distance` of the bottom point
    (by default a tenth of `refine_distance`), `far_size` beyond `refine_distance` (by
    default radius / 2)."""
    r = radius
    with session("hemisphere") as gmsh:
        occ = gmsh.model.occ
        ball = occ.addSphere(0, r, 0, r)
        upper = occ.addBox(-2 * r, r, -2 * r, 4 * r, 2 * r, 4 * r)
        half, _ = occ.cut([(3, ball)], [(3, upper)])
        # The cap: a ball's surface below the height where the contact angle ends.
        cap_height = r - r * math.cos(math.radians(contact_angle) / 2)
        below = occ.addBox(-2 * r, -r, -2 * r, 4 * r, r + cap_height, 4 * r)
        pieces, _ = occ.fragment(half, [(3, below)])
        occ.synchronize()
        # Keep the body's pieces; drop what lies outside the half ball (the rest of the box).
        body = []
        for dim, tag in gmsh.model.getEntities(3):
            x, y, z = occ.getCenterOfMass(dim, tag)
            if x * x + (y - r) ** 2 + z * z < r * r:
                body.append(tag)
            else:
                occ.remove([(dim, tag)], recursive=True)
        occ.synchronize()
        body = [tag for _, tag in gmsh.model.getEntities(3)]
        contact, clamp = [], []
        for _, tag in gmsh.model.getBoundary([(3, t) for t in body], oriented=False):
            x, y, z = occ.getCenterOfMass(2, tag)
            if abs(y - r) < 1e-9 * r:
                clamp.append(tag)
            elif y < cap_height:
                contact.append(tag)
        gmsh.model.addPhysicalGroup(3, body, name="body")
        gmsh.model.addPhysicalGroup(2, contact, name="contact")
        gmsh.model.addPhysicalGroup(2, clamp, name="clamp")
        # The bottom point, embedded in the cap, is where the elements are finest.
        bottom = occ.addPoint(0, 0, 0)
        occ.synchronize()
        gmsh.model.mesh.embed(0, [bottom], 2, contact[0])
        _refine_near(gmsh, bottom, contact_size, far_size, refine_distance or r / 2, fine_distance)
        gmsh.model.mesh.generate(3)
        return write(gmsh, path, version)


def plate_with_hole(path, width=0.1, height=0.06, hole=(0.05, 0.03, 0.015), size=0.005, version="4.1"):
    """A rectangle (bottom "contact", top "clamp") with a circular hole (x, y, radius)."""
    with session("plate_with_hole") as gmsh:
        occ = gmsh.model.occ
        plate = occ.addRectangle(0, 0, 0, width, height)
        disk = occ.addDisk(hole[0], hole[1], 0, hole[2], hole[2])
        occ.cut([(2, plate)], [(2, disk)])
        occ.synchronize()
        surface = gmsh.model.getEntities(2)[0][1]
        bottom, top = [], []
        for dim, tag in gmsh.model.getBoundary([(2, surface)], oriented=False):
            x0, y0, _, x1, y1, _ = gmsh.model.getBoundingBox(dim, tag)
            if abs(y1 - y0) < 1e-6 and abs(y0) < 1e-6:  # OCC pads its boxes by its tolerance
                bottom.append(tag)
            elif abs(y1 - y0) < 1e-6 and abs(y1 - height) < 1e-6:
                top.append(tag)
        gmsh.model.addPhysicalGroup(2, [surface], name="body")
        gmsh.model.addPhysicalGroup(1, bottom, name="contact")
        gmsh.model.addPhysicalGroup(1, top, name="clamp")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        return write(gmsh, path, version)


def pad3d(path, width=0.06, height=0.02, depth=0.04, chamfer=0.004, slot_width=0.006,
          slot_depth=0.008, size=4e-3, contact_size=None, version="4.1"):
    """pad()'s outline extruded `depth` along z: a 3D pad of tetrahedra with two chamfered
    bottom edges (along z) and a slot across its bottom face; the two bottom faces beside the
    slot are "contact", the top face "clamp". Cells of `size`, of `contact_size` on the
    contact faces if given."""
    w, h, c, sw, sd = width, height, chamfer, slot_width, slot_depth
    outline = [(c, 0), (w / 2 - sw / 2, 0), (w / 2 - sw / 2, sd), (w / 2 + sw / 2, sd),
               (w / 2 + sw / 2, 0), (w - c, 0), (w, c), (w, h), (0, h), (0, c)]
    with session("pad3d") as gmsh:
        occ = gmsh.model.occ
        points = [occ.addPoint(x, y, 0) for x, y in outline]
        lines = [occ.addLine(points[k], points[(k + 1) % len(points)]) for k in range(len(points))]
        face = occ.addPlaneSurface([occ.addCurveLoop(lines)])
        volume = [tag for dim, tag in occ.extrude([(2, face)], 0, 0, depth) if dim == 3]
        occ.synchronize()
        contact, clamp = [], []
        for _, tag in gmsh.model.getBoundary([(3, t) for t in volume], oriented=False):
            x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(2, tag)
            if abs(y1 - y0) < 1e-6 and abs(y0) < 1e-6:  # OCC pads its boxes by its tolerance
                contact.append(tag)
            elif abs(y1 - y0) < 1e-6 and abs(y1 - h) < 1e-6:
                clamp.append(tag)
        gmsh.model.addPhysicalGroup(3, volume, name="body")
        gmsh.model.addPhysicalGroup(2, contact, name="contact")
        gmsh.model.addPhysicalGroup(2, clamp, name="clamp")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        if contact_size:
            _refine_near(gmsh, contact, contact_size, size, 2 * (size - contact_size), 0, "SurfacesList")
        gmsh.model.mesh.generate(3)
        return write(gmsh, path, version)


def pad(path, width=0.06, height=0.02, chamfer=0.004, slot_width=0.006, slot_depth=0.008,
        size=1e-3, contact_size=None, growth=0.2, version="4.1"):
    """A brake-pad-like block: chamfered bottom corners, a slot cut up from the middle of its
    bottom face; the two bottom faces beside the slot are "contact", the top face "clamp".
    With contact_size, the cells along the contact faces are that size, growing away from
    them at the rate `growth` up to `size`."""
    w, h, c, sw, sd = width, height, chamfer, slot_width, slot_depth
    outline = [(c, 0), (w / 2 - sw / 2, 0), (w / 2 - sw / 2, sd), (w / 2 + sw / 2, sd),
               (w / 2 + sw / 2, 0), (w - c, 0), (w, c), (w, h), (0, h), (0, c)]
    with session("pad") as gmsh:
        geo = gmsh.model.geo
        points = [geo.addPoint(x, y, 0) for x, y in outline]
        lines = [geo.addLine(points[k], points[(k + 1) % len(points)]) for k in range(len(points))]
        surface = geo.addPlaneSurface([geo.addCurveLoop(lines)])
        geo.synchronize()
        gmsh.model.addPhysicalGroup(2, [surface], name="body")
        gmsh.model.addPhysicalGroup(1, [lines[0], lines[4]], name="contact")
        gmsh.model.addPhysicalGroup(1, [lines[7]], name="clamp")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        if contact_size:
            field = gmsh.model.mesh.field
            d = field.add("Distance")
            field.setNumbers(d, "CurvesList", [lines[0], lines[4]])
            field.setNumber(d, "Sampling", int(2 * width / contact_size) + 10)
            t = field.add("Threshold")
            field.setNumber(t, "InField", d)
            field.setNumber(t, "SizeMin", contact_size)
            field.setNumber(t, "SizeMax", size)
            field.setNumber(t, "DistMin", 0)
            field.setNumber(t, "DistMax", (size - contact_size) / growth)
            field.setAsBackgroundMesh(t)
            for option in ("Mesh.MeshSizeExtendFromBoundary", "Mesh.MeshSizeFromPoints",
                           "Mesh.MeshSizeFromCurvature"):
                gmsh.option.setNumber(option, 0)
        gmsh.model.mesh.generate(2)
        return write(gmsh, path, version)
