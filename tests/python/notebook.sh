#!/usr/bin/env bash
# Executes the example notebook headless, as Jupyter would for a reader (jupyter-nbconvert
# --execute: a cell that raises fails the test), in a folder of its own, then checks what it
# shows: no warnings or errors on stderr, and its pictures (the plot of kinetic energy against
# e, the figure, the bouncing ball) as PNG outputs, written beside it as output-N.png to look at.
# Usage: notebook.sh NBCONVERT PYTHON NOTEBOOK WORK_DIR   (WORK_DIR is emptied first)
set -euo pipefail
nbconvert=$1 python=$2 notebook=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
cp "$notebook" "$work/notebook.ipynb"
# Jupyter's, IPython's and matplotlib's own files in the work folder too, not in $HOME.
export JUPYTER_RUNTIME_DIR=$work/jupyter IPYTHONDIR=$work/ipython MPLCONFIGDIR=$work/matplotlib
"$nbconvert" --to notebook --execute --ExecutePreprocessor.timeout=300 \
  --ExecutePreprocessor.kernel_name=python3 --output executed.ipynb "$work/notebook.ipynb" 2>"$work/nbconvert.log" ||
  { cat "$work/nbconvert.log"; exit 1; }
"$python" - "$work" <<'PY'
import base64, json, pathlib, sys
work = pathlib.Path(sys.argv[1])
nb = json.loads((work / "executed.ipynb").read_text())
outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
problems = [o["text"] if isinstance(o["text"], str) else "".join(o["text"])
            for o in outputs if o.get("name") == "stderr"]
images = [o["data"]["image/png"] for o in outputs if "image/png" in o.get("data", {})]
for k, png in enumerate(images, 1):
    (work / f"output-{k}.png").write_bytes(base64.b64decode(png))
text = "".join("".join(o.get("text", "")) for o in outputs)
if problems:
    sys.exit("the notebook wrote on stderr:\n" + "\n".join(problems))
if len(images) != 3:
    sys.exit(f"expected 3 pictures (the energy plot, the figure, the ball), got {len(images)}")
if "energy_gain: True" not in text:
    sys.exit("the one-step Coulomb model at e = 0.9 should gain energy (Kane's paradox):\n" + text)
print(f"notebook: ran; {len(images)} pictures in {work}")
PY
