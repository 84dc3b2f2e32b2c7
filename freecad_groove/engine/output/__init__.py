"""The output layer: every control's program syntax (``syntax.Target``, one
table each in ``targets.py``), the one writer (``writer.Writer``), the one
program builder (``program.ProgramBuilder``), and writing files atomically
(``files.py``)."""
