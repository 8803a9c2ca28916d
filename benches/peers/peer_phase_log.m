% Headless replacement for plotData_phase_paper at the end of main_rod.m:
% one line per phase of the authors' run, read by the workbook's peer
% runner (benches/peers/authors_octave.py):
%   PEERLOG i t_end phase exit theta theta_dot x_c
% with the state at the end of the phase (the last point of D1.raw(i)).
% Written for the workbook; not part of the authors' code.
function peer_phase_log (D, D1)
  for i = 1:numel (D.phase)
    r = D1.raw(i);
    printf ("PEERLOG %d %.17g %s %s %.17g %.17g %.17g\n", i, r.time(end), ...
            D.phase{i}, D.code{i}, r.state.th(end), r.state.dth(end), ...
            r.state.xc(end));
  end
end
