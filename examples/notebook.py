# %% [markdown]
# # cellproj in a notebook
# Cells in the percent format (Jupyter through jupytext, VS Code, Spyder run them as cells); each
# cell's last line is what a notebook shows. Run from the clone's folder:
# `PYTHONPATH=build/python python3 examples/notebook.py` runs it whole (tests/python runs it too).

# %%
import numpy as np

import cellproj

mesh = cellproj.read("scenes/default.vtu")  # any file `cellproj info` reads; or a VTK, PyVista or meshio object
mesh.fields, mesh.n_cells

# %% [markdown]
# One call, PyVista's keywords: the picture shows itself (`Image._repr_png_`) and saves itself.

# %%
image = cellproj.render(mesh, scalars="temperature", cmap="viridis", view="iso", azimuth=30, legend=True,
                        title="temperature", size=(480, 360))
image.save("temperature.png")
image

# %% [markdown]
# Colour by one field, opacity by another (ParaView's separate opacity array): here the
# temperature's distance from its median makes the extremes opaque and the bulk clear.

# %%
t = mesh.field("temperature")
mesh.add_field("deviation", np.abs(t - np.median(t)))
cellproj.render(mesh, scalars="temperature", opacity_field="deviation", opacity="ramp", cmap="inferno",
                view="iso", legend=True, size=(480, 360))

# %% [markdown]
# Half the mesh clipped away, a fast method against the exact reference: the images are numpy
# arrays (premultiplied RGBA floats), so their difference is one line.

# %%
half = dict(scalars="temperature", clip=(0, 0, 0, 1, 0, 0), view="+z", size=(256, 256))
fast = cellproj.render(mesh, method="pt-linear", **half)
exact = cellproj.render(mesh, method="exact", **half)
error = float(np.abs(fast - exact).max())
print("pt-linear against exact: largest difference %.2g (%s, %s)" % (error, fast.stats["method"],
                                                                     exact.stats["method"]))

# %% [markdown]
# A turntable as a movie, each frame encoded as it is made.

# %%
with cellproj.Movie("turn.gif", fps=12) as movie:
    for azimuth in range(0, 360, 30):
        movie.add(cellproj.render(mesh, scalars="temperature", view="iso", azimuth=azimuth, size=(160, 120)))
movie.frames
