#!/usr/bin/env bash
# Create <repo>/.venv with NumPy < 2 and the `gdist` package (Kirsanov's exact
# MMP geodesics) built from source, for examples/benchmark/bench_vs_gdist.py.
#
# The prebuilt gdist wheels are compiled against NumPy 1 and fail to import
# under NumPy 2, so NumPy is pinned below 2 and gdist is compiled here against
# it (without build isolation, so the build sees the pinned NumPy).
#
# Idempotent: does nothing when the venv already imports gdist.
# Environment: PYTHON selects the interpreter (default: python3, CPython 3.11).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
venv="$repo/.venv"
python="${PYTHON:-python3}"

smoke_test() {
    "$venv/bin/python" - <<'EOF'
import numpy as np
import gdist

# Unit square split into two triangles: distance from corner 0 to corner 2 is sqrt(2).
vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
triangles = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32)
d = gdist.compute_gdist(vertices, triangles, source_indices=np.array([0], dtype=np.int32))
assert np.allclose(d, [0.0, 1.0, 2 ** 0.5, 1.0]), d
print(f"gdist smoke test passed (numpy {np.__version__})")
EOF
}

if [ -x "$venv/bin/python" ] && "$venv/bin/python" -c 'import gdist' 2>/dev/null; then
    echo "setup_venv: $venv already provides gdist" >&2
    smoke_test
    exit 0
fi

echo "setup_venv: creating $venv with $("$python" --version 2>&1)" >&2
"$python" -m venv "$venv"
"$venv/bin/python" -m pip install --quiet "numpy<2" scipy cython setuptools wheel
"$venv/bin/python" -m pip install --quiet --no-build-isolation --no-binary gdist gdist
smoke_test
