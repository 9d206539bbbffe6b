"""What is measured from runs, beside theory: the oscillator's closed forms and analysis,
resonance sweeps, and the model of matter's measurements. Draws nothing."""
