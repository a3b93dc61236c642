"""The deep audit of the generated kernels (``make audit``): :mod:`.run` measures each
emitted kernel in C and Python on the points of :mod:`.points`, random, hard and found by
an adversarial search, against the Result's derived form at high precision."""
