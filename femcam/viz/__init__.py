"""Plots and renderings. One module per concept (``analytic``, ``fe``, ``sweep``, ``wear``,
``synthesis``); matplotlib (:func:`femcam.viz._mpl.pyplot`) and pyvista are imported inside the
functions so that the analytic chain never needs them. The plots draw results; they never
compute or solve.

Every ``plot_*`` function takes the object to draw (a ``SceneState``, ``SweepResult``,
``WearMap``, ``EvolutionResult``, ``SynthesisResult`` or ``ContactResult``), ``path`` (the PNG
to write, str or Path) and keyword options, each documented in its numpydoc Parameters (units
included); each returns the path written.
"""
