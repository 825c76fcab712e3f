"""What can be known of a macOS binary without a Mac: its Mach-O facts, read with Debian's
llvm-14 tools (llvm-lipo, llvm-otool, llvm-nm; scripts/setup.sh installs llvm-14 for the macOS
rows of platforms.json). python_tests/test_portable.py checks the FMUs' macOS binaries with
these, benchmarks/macos_cost.py reports them."""
import pathlib
import re
import subprocess

LIBSYSTEM = "/usr/lib/libSystem.B.dylib"
# Every dylib's two symbols and libc++'s replaceable operator new/delete, which a dylib linked
# with libc++ exports with default visibility (docs/building.md): nothing else but fmi2*/fmi3*.
OTHER_EXPORTS = {"__mh_dylib_header", "___dso_handle"} | {
    "__Zda" + s for s in ("Pv", "PvSt11align_val_t", "Pvm", "PvmSt11align_val_t")} | {
    "__Zdl" + s for s in ("Pv", "PvSt11align_val_t", "Pvm", "PvmSt11align_val_t")} | {
    "__Zn" + s for s in ("am", "amSt11align_val_t", "wm", "wmSt11align_val_t")}


def tool(*args):
    return subprocess.run([str(a) for a in args], check=True, capture_output=True, text=True).stdout


def architectures(path):
    """lipo's names of the architectures a (universal or thin) binary holds."""
    return set(tool("llvm-lipo-14", "-archs", path).split())


def thin(path, arch, folder):
    """The one architecture's slice of a universal binary, as a file in `folder` (a thin
    binary of that architecture is returned as it is)."""
    if architectures(path) == {arch}:
        return pathlib.Path(path)
    out = pathlib.Path(folder) / f"{pathlib.Path(path).stem}-{arch}{pathlib.Path(path).suffix}"
    tool("llvm-lipo-14", "-thin", arch, "-output", out, path)
    return out


def facts(dylib):
    """CPU type, file type, the libraries it loads, its minimum macOS, whether it carries a code
    signature, its exported and imported symbols (one thin binary)."""
    header = tool("llvm-otool-14", "-hv", dylib).split("\n")[-2].split()
    libraries = [line.split(" (")[0].strip() for line in tool("llvm-otool-14", "-L", dylib).splitlines()[1:]]
    commands = tool("llvm-otool-14", "-l", dylib)
    minos = re.search(r"minos (\S+)", commands)
    return {"cpu": header[1], "filetype": header[4],
            "libraries": libraries[1:],  # the first is the dylib's own install name
            "install_name": libraries[0] if libraries else None,
            "minos": minos[1] if minos else None,
            "signed": "LC_CODE_SIGNATURE" in commands,
            "exports": {line.split()[-1] for line in tool("llvm-nm-14", "-gU", dylib).splitlines()},
            "imports": set(tool("llvm-nm-14", "-u", dylib).split())}
