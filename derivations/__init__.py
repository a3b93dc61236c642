"""One package per memoir, one module per section; each package exposes SPECS."""
