"""Plots and renderings. One module per concept (``analytic``, ``fe``, ``sweep``, ``wear``,
``synthesis``); matplotlib (:func:`femcam.viz._mpl.pyplot`) and pyvista are imported inside the
functions so that the analytic chain never needs them. The plots draw results; they never
compute or solve.

Parameters and returns common to every ``plot_*`` function: the object to draw (a
``SceneState``, ``SweepResult``, ``WearMap``, ``EvolutionResult``, ``SynthesisResult`` or
``ContactResult``, as each names it), ``path`` (the PNG to write, str or Path) and keyword
options (``title`` and the ones documented, units in each docstring). Each returns the path
written.
"""
