# %% [markdown]
# # The SG2150 exam of 2015-10-29, solved from Python
#
# A notebook in the percent format (cells start with `# %%`): open it in Jupyter
# (with jupytext) or VS Code, or run it as a script. `tests/api/test_notebook.py` runs
# it headless on every change. See docs/api.md.

# %%
from pathlib import Path

import rbdsolve

try:
    display  # Jupyter's, a builtin in a notebook
except NameError:  # run as a script: show what a notebook would typeset, as HTML
    def display(obj):
        print(obj._repr_html_())

EXAM = Path(__file__).resolve().parents[1] / "problems" / "sg2150-2015-10-29"

# %% [markdown]
# Load every problem of the exam (a file each) and solve it with the command line's
# defaults: the exact route, a budget of 60 s per question.

# %%
problems = [rbdsolve.load(path) for path in sorted(EXAM.glob("p*.yaml")) if ".expected" not in path.name]
results = [rbdsolve.solve(problem) for problem in problems]
for result in results:
    print(result)

# %% [markdown]
# Problem 1: the two rods' frequencies of small oscillation are sympy expressions.
# Substitute the values of a lab set-up (g = 9.81 m/s², r = 0.4 m) and differentiate
# with respect to r.

# %%
rods = results[0]
frequencies = rods["modes"].answers.frequencies
g, r = rods.symbols["g"], rods.symbols["r"]
at_lab = [rods.subs(w, g=9.81, r=0.4) for w in frequencies]
print("ω at g = 9.81, r = 0.4:", [float(w) for w in at_lab])
print("dω₁/dr =", frequencies[0].diff(r))

# %% [markdown]
# The modes question, typeset (MathML in the HTML a notebook shows), then the whole
# worked solution of problem 2, the impact.

# %%
display(rods["modes"])
display(results[1])
