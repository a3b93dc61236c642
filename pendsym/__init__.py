"""pendsym: symbolic rebuild and independent verification of the perturbation theory of the pendulum."""
