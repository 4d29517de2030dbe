"""The PEP 517 build backend of `pip install .` (pyproject.toml): the project's own CMake build, packed as a wheel.

build_wheel configures the project (Release, without tests and benchmarks, for the interpreter pip runs
under) in build/wheel/ of the source tree, or uses the configured build tree named by DFVN_CMAKE_BUILD_DIR
as it is; builds the target dfvn_python (libdfvn and the module); installs the CMake components python
(the package) and python_wheel (libdfvn, into the package folder, where the module finds it through
$ORIGIN) into a staging folder; and zips that package with its metadata. Nothing is downloaded: NumPy
and the build tools are Debian's (pip install . --no-build-isolation).
"""
import base64
import hashlib
import os
import pathlib
import re
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
NAME = "dfvn"


def _version():
    """The project's version, from CMakeLists.txt's project() (the one DFVN_VERSION and dfvn.__version__ carry)."""
    found = re.search(r"project\(\s*\w+\s+VERSION\s+([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not found:
        raise RuntimeError("dfvn_build: no VERSION in CMakeLists.txt's project()")
    return found.group(1)


def _metadata():
    return (f"Metadata-Version: 2.1\nName: {NAME}\nVersion: {_version()}\n"
            "Summary: Divergence-free vector noise, curl-noise jittering and scipy.stats.qmc point engines\n"
            "Requires-Python: >=3.8\nRequires-Dist: numpy\nProvides-Extra: scipy\n"
            "Requires-Dist: scipy; extra == \"scipy\"\n")


def _tag():
    """cpXY-cpXY-<platform>: the wheel holds an extension for this interpreter and machine only."""
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{python}-{python}-{platform}"


def _run(command):
    print("dfvn_build:", " ".join(map(str, command)), file=sys.stderr, flush=True)
    subprocess.run([str(c) for c in command], check=True, stdout=sys.stderr)


def _build_tree():
    given = os.environ.get("DFVN_CMAKE_BUILD_DIR")
    if given:
        tree = pathlib.Path(given).resolve()
        if not (tree / "CMakeCache.txt").exists():
            raise RuntimeError(f"dfvn_build: DFVN_CMAKE_BUILD_DIR={given} is not a configured CMake build tree")
        return tree
    tree = ROOT / "build" / "wheel"
    _run(["cmake", "-S", ROOT, "-B", tree, "-DCMAKE_BUILD_TYPE=Release", "-DDFVN_BUILD_TESTS=OFF",
          "-DDFVN_BUILD_BENCH=OFF", f"-DPython_EXECUTABLE={sys.executable}"])
    return tree


def _package_files(staging):
    """(name in the wheel, bytes) of the installed package: a symbolic link (libdfvn's soname, which the module
    needs) carries the file it points to, which is not added again under its own name."""
    inits = list(staging.rglob(f"{NAME}/__init__.py"))
    if len(inits) != 1:
        raise RuntimeError(f"dfvn_build: the install put {len(inits)} packages {NAME} under {staging}")
    package = inits[0].parent
    linked = {p.resolve() for p in package.iterdir() if p.is_symlink()}
    files = []
    for path in sorted(package.iterdir()):
        if path.is_dir() or (not path.is_symlink() and path.resolve() in linked):
            continue
        files.append((f"{NAME}/{path.name}", path.resolve().read_bytes()))
    return files


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


# PEP 517 hooks ------------------------------------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def _wheel_file():
    return f"Wheel-Version: 1.0\nGenerator: dfvn_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n"


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    """The dist-info folder without building (pip asks for it first; build_wheel would build twice)."""
    info = pathlib.Path(metadata_directory) / f"{NAME}-{_version()}.dist-info"
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata())
    (info / "WHEEL").write_text(_wheel_file())
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    tree = _build_tree()
    jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
    _run(["cmake", "--build", tree, "--target", "dfvn_python", "--parallel", jobs])
    with tempfile.TemporaryDirectory(prefix="dfvn-wheel-") as staging:
        for component in ("python", "python_wheel"):
            _run(["cmake", "--install", tree, "--prefix", staging, "--component", component])
        files = _package_files(pathlib.Path(staging))
    info = f"{NAME}-{_version()}.dist-info"
    files += [(f"{info}/METADATA", _metadata().encode()),
              (f"{info}/WHEEL", _wheel_file().encode())]
    record = "\n".join([_record_line(name, data) for name, data in files] + [f"{info}/RECORD,,"]) + "\n"
    wheel = f"{NAME}-{_version()}-{_tag()}.whl"
    with zipfile.ZipFile(pathlib.Path(wheel_directory) / wheel, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in files:
            entry = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            entry.external_attr = (0o755 if name.endswith(".so") or ".so." in name else 0o644) << 16
            archive.writestr(entry, data, zipfile.ZIP_DEFLATED)
        archive.writestr(zipfile.ZipInfo(f"{info}/RECORD", date_time=(1980, 1, 1, 0, 0, 0)), record)
    return wheel


def build_sdist(sdist_directory, config_settings=None):
    """The tracked source tree (git archive) as dfvn-<version>.tar.gz."""
    name = f"{NAME}-{_version()}"
    _run(["git", "-C", ROOT, "archive", "--format=tar.gz", f"--prefix={name}/", "-o",
          pathlib.Path(sdist_directory).resolve() / f"{name}.tar.gz", "HEAD"])
    return f"{name}.tar.gz"
