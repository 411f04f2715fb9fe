"""The GRBL 1.1 / grblHAL driver: a sans-IO session (``session.GrblSession``) and its
parser, codes, settings and dialect. No Qt."""
