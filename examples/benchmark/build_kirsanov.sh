#!/usr/bin/env bash
# Build kirsanov_driver.cpp against Kirsanov's exact MMP as the gdist source distribution
# ships it (its `geodesic_library` headers), into <repo>/bench-results/kirsanov/ (gitignored):
# the whole-process peer of `bench_vs_gdist.py --kirsanov-driver`. The source distribution is
# fetched from PyPI; nothing of it enters the repository.
#
# Idempotent: does nothing when the driver is already built. Environment: CXX (default g++),
# GDIST_VERSION (default 2.1.0).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
dir="$repo/bench-results/kirsanov"
driver="$dir/kirsanov_driver"
version="${GDIST_VERSION:-2.1.0}"

if [ -x "$driver" ]; then
    echo "build_kirsanov: $driver already built" >&2
    exit 0
fi
mkdir -p "$dir"
if [ ! -d "$dir/gdist-$version" ]; then
    python3 - "$version" "$dir/gdist.tar.gz" <<'PY'
import json, sys, urllib.request
version, target = sys.argv[1], sys.argv[2]
project = json.load(urllib.request.urlopen("https://pypi.org/pypi/gdist/json", timeout=60))
url = next(f["url"] for f in project["releases"][version] if f["packagetype"] == "sdist")
urllib.request.urlretrieve(url, target)
PY
    tar -xzf "$dir/gdist.tar.gz" -C "$dir"
fi
"${CXX:-g++}" -O3 -DNDEBUG -std=c++17 -w -I "$dir/gdist-$version/geodesic_library" \
    "$repo/examples/benchmark/kirsanov_driver.cpp" -o "$driver"
echo "build_kirsanov: built $driver (gdist $version)" >&2
