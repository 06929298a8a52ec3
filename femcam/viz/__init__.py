"""Plots and renderings. One module per concept (``analytic``, ``fe``, ``sweep``, ``wear``,
``synthesis``); matplotlib and pyvista are imported inside the functions so that the analytic
chain never needs them."""
