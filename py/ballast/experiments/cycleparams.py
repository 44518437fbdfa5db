"""The parameters of the cyclic piece (:mod:`.cyclic`), declared once for every cyclic experiment, with the
same unit and meaning in each: a state every saveEvery load cycles, a VTK frame every vtk load cycles.
Needs no YADE."""
from ..params import NUMBER_NONNEGATIVE, Param, nonNegative

SAVE_EVERY = Param(0.0, 'cycles', 'besides the states at the start and the end, save the state every saveEvery load '
                   'cycles: a whole number after the cycle closes (state-cycle<N>.yade.gz, N the cycles done: reopen '
                   'or continueFrom goes on from it), a fraction within cycles (0.25: four states a cycle, '
                   'state-iter<step>.yade.gz); 0 = only those two', nonNegative, NUMBER_NONNEGATIVE)
VTK = Param(0.0, 'cycles', 'a VTK frame (the grains with their state, the contact force network, the walls) every vtk '
            'load cycles from the start of loading and one at its end, listed in a .pvd for ParaView (0.1: ten frames '
            'a cycle; 0 = none)', nonNegative, NUMBER_NONNEGATIVE)
PARAMS = {'saveEvery': SAVE_EVERY, 'vtk': VTK}

