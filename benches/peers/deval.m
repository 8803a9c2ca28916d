% deval shim for GNU Octave (which has no deval): the solution of an ode45
% run evaluated at the times t, by linear interpolation of the accepted
% points sol.x, sol.y. Exact at the points themselves, which is all the
% authors' fsm.m reads (the state at the end of each phase); between points
% it is a plotting approximation only. Written for the workbook's peer
% runner (benches/peers/authors_octave.py); not part of the authors' code.
function Z = deval (sol, t)
  x = sol.x(:);
  y = sol.y;
  if (size (y, 2) != numel (x))
    y = y.';
  end
  if (numel (x) == 1)
    Z = repmat (y(:, 1), 1, numel (t));
    return;
  end
  % drop repeated times (a zero-length last step), keeping the later value
  keep = [diff(x) > 0; true];
  x = x(keep);
  y = y(:, keep);
  Z = interp1 (x, y.', t(:), 'linear').';
  % the end points exactly (interp1 returns NaN outside, ends are exact anyway)
  Z(:, t(:) <= x(1)) = repmat (y(:, 1), 1, nnz (t(:) <= x(1)));
  Z(:, t(:) >= x(end)) = repmat (y(:, end), 1, nnz (t(:) >= x(end)));
end
