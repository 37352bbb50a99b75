# a profile for the command tests: jaw opens the mouth less
jaw open_jaw 512
nod head_pitch 1745.329
