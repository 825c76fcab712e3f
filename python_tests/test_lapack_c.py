"""The LU routines' C form (f2c, made by the build from the vendored Fortran,
third_party/CMakeLists.txt) against the Fortran itself compiled as reference LAPACK's build
does (gfortran -O2 -frecursive, dlamch at -O0): dgetrf and dgetrs on random matrices across
the blocked path's size 64, and dlamch's ten constants, give the same bits. Every platform
compiles this same C form, and the platform jobs compare their outputs with linux64's."""
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[1]
LAPACK = ROOT / "third_party" / "lapack-3.11.0"
GENERATED = ROOT / "build" / "third_party" / "lapack_c"
ROUTINES = ["dgetrf", "dgetrf2", "dgetrs", "dlaswp", "dgemm", "dtrsm", "dscal", "dswap",
            "idamax", "lsame"]
DRIVER = ROOT / "tests_cpp" / "lu_driver.c"


def run(program):
    return subprocess.run([str(program)], check=True, capture_output=True).stdout


def test_the_c_form_rounds_as_the_fortran(tmp_path):
    fortran = tmp_path / "fortran_lu"
    objects = []
    for routine in ROUTINES + ["dlamch"]:
        obj = tmp_path / f"{routine}.o"
        flags = ["-O0"] if routine == "dlamch" else ["-O2", "-frecursive"]
        subprocess.run(["gfortran", *flags, "-c", str(LAPACK / f"{routine}.f"), "-o", str(obj)],
                       check=True)
        objects.append(str(obj))
    # ilaenv and xerbla from lapack_support.c, dlamch the Fortran's: the first definition
    # (dlamch.o, before lapack_support.c) is the one linked.
    support = ROOT / "third_party" / "lapack_support.c"
    subprocess.run(["gcc", "-O2", str(DRIVER), *objects, str(support),
                    "-Wl,--allow-multiple-definition", "-o", str(fortran)], check=True)
    # The C form as the build made it, compiled as the build compiles it.
    c = tmp_path / "c_lu"
    sources = [str(GENERATED / f"{routine}.c") for routine in ROUTINES]
    subprocess.run(["gcc", "-O2", "-ffp-contract=off", "-I", str(ROOT / "third_party" / "lapack_c"),
                    str(DRIVER), *sources, str(support), "-o", str(c)], check=True)
    expected, got = run(fortran), run(c)
    assert len(expected) > 1_000_000  # every size ran
    assert got == expected


def test_the_c_form_is_what_f2c_makes_of_the_vendored_fortran():
    """Made by the build, not kept: each file names f2c and its Fortran routine."""
    for routine in ROUTINES:
        text = (GENERATED / f"{routine}.c").read_text()
        assert "translated by f2c" in text
        assert f"{routine}_(" in text
