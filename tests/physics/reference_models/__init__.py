"""Independent reference models for the vehicle checks: linear lateral models written from the
textbook equations (Wickens 2003; Iwnicki 2006; Garg & Dukkipati 1984; Boocock 1969) in numpy
and scipy, never from the core's code. They are test oracles, not part of the package; the
``README.md`` next to this file says what each model is, its sources and its assumptions."""
