"""The turning check: a CAM Job's Groove ops simulated on the turned section
of its stock (a command over the ops, not an op).

    check.py  verify_job(): the Job read into the check's plain data (freecad_groove.verify.turning
              judges it), each op's CycleTime set
    gui/      command.py (Check turning), panel.py (the figures per op), preview.py (the section drawn
              in the 3D view while the panel is open)
"""
