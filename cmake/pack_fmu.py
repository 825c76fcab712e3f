"""Packs an FMU folder into a .fmu (zip): python pack_fmu.py FOLDER OUTPUT.

Everything is deflated except the Linux binary (binaries/linux64, FMI 3.0's
binaries/x86_64-linux), which is stored: fmpy extracts every
platform's binaries on each simulate_fmu, and inflating the 1.4 MB .so took 7.5 ms of a
25 ms one-step run (benchmarks/results/portable.md). Stored, it is a copy. The win64 DLL stays
deflated, or the FMU would pass 3 MB."""
import os
import pathlib
import sys
import zipfile

folder, output = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
files = sorted(p for p in folder.rglob("*") if p.is_file())
files.sort(key=lambda p: p.name != "modelDescription.xml")  # first, as tools expect
tmp = output.with_suffix(".tmp")
with zipfile.ZipFile(tmp, "w") as z:
    for path in files:
        name = path.relative_to(folder).as_posix()
        stored = name.startswith(("binaries/linux64/", "binaries/x86_64-linux/"))
        z.write(path, name, compress_type=zipfile.ZIP_STORED if stored else zipfile.ZIP_DEFLATED,
                compresslevel=None if stored else 9)
os.replace(tmp, output)
