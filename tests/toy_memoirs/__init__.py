"""A memoir package that lives in the tests: its sub-packages are discovered like derivations/'s."""
