"""Building blocks of exercise checks: the student's package, a probe of a
launch, the verdict.  `labkit.exercises` is the API lessons call."""
