namespace URWPGSim2D.Hosting;

/// <summary>
/// Runs a strategy's <see cref="IStrategy.Decide"/> on a dedicated background thread, measured by a
/// <see cref="StrategyClock"/> (the CPU time of that thread in a real match, and the call's wall time).
/// The caller says how long it waits for a call; a call past that is abandoned (its answer is discarded
/// even if it arrives before the caller looks, and the runner answers <see cref="Outcome.TimedOut"/>
/// while it is still busy), so a strategy that hangs cannot stop the match.
/// </summary>
internal sealed class IsolatedStrategyRunner
{
    private readonly IStrategy _strategy;
    private readonly StrategyClock _clock;
    private readonly Decision[] _work;
    private readonly SemaphoreSlim _start = new(0);
    private readonly SemaphoreSlim _done = new(0);
    private MatchSnapshotWriter? _snapshot;
    private int[] _fish = [];
    private Exception? _error;
    private TimeSpan _cpu;
    private TimeSpan _wall;
    private bool _pending;
    private volatile bool _stopped;
    private DebugRecorder? _drawings;
    private StrategyLog? _log;

    public IsolatedStrategyRunner(IStrategy strategy, int fishCount, int team, StrategyClock clock)
    {
        _strategy = strategy;
        _clock = clock;
        _work = new Decision[fishCount];
        ConsoleRouter.Install(); // what the strategy prints passes the router: escaped, or into its log
        var thread = new Thread(Loop) { IsBackground = true, Name = $"strategy team {team}" };
        thread.Start();
    }

    /// <summary>Outcome of one call.</summary>
    public enum Outcome
    {
        /// <summary>Finished in the time waited; decisions updated.</summary>
        Decided,

        /// <summary>Threw; decisions unchanged.</summary>
        Threw,

        /// <summary>Past the time waited, or still busy with a call given up on; decisions unchanged.</summary>
        TimedOut,
    }

    /// <summary>
    /// Asks for decisions and waits for them up to <paramref name="cpuLimit"/> of the call's CPU time and
    /// <paramref name="wallLimit"/> of wall time (<see cref="Timeout.InfiniteTimeSpan"/>: as long as the call takes).
    /// </summary>
    /// <param name="snapshot">What the strategy sees.</param>
    /// <param name="fish">The fish it decides for.</param>
    /// <param name="decisions">The decisions in force; replaced when the call decides.</param>
    /// <param name="cpuLimit">CPU time after which the call is given up.</param>
    /// <param name="wallLimit">Wall time after which the call is given up.</param>
    /// <param name="error">What the call threw, for <see cref="Outcome.Threw"/>.</param>
    /// <param name="cpu">CPU time the call used (when it finished).</param>
    /// <param name="wall">Wall time the call took (when it finished).</param>
    public Outcome Decide(MatchSnapshot snapshot, int[] fish, Span<Decision> decisions, TimeSpan cpuLimit, TimeSpan wallLimit, out Exception? error, out TimeSpan cpu, out TimeSpan wall)
    {
        error = null;
        cpu = wall = TimeSpan.Zero;
        if (_pending)
        {
            if (!_clock.AbandonedCallReturned(_done))
            {
                return Outcome.TimedOut;
            }

            _pending = false; // the abandoned call's answer is dropped here
        }

        // The strategy reads its own copy: a call given up on may go on reading while the next
        // cycles rewrite the match's snapshot and the referee's variables.
        decisions.CopyTo(_work);
        if (_snapshot is null)
        {
            _snapshot = MatchSnapshotWriter.CopyOf(snapshot);
        }
        else
        {
            _snapshot.CopyFrom(snapshot);
        }

        _fish = fish;
        _error = null;
        _pending = true;
        _clock.Arm(cpuLimit);
        _start.Release();
        if (!_clock.WaitForCall(_done, cpuLimit, wallLimit))
        {
            return Outcome.TimedOut;
        }

        _pending = false;
        cpu = _cpu;
        wall = _wall;
        if (_error is not null)
        {
            error = _error;
            return Outcome.Threw;
        }

        _work.CopyTo(decisions);
        return Outcome.Decided;
    }

    /// <summary>
    /// The debug drawings of the last call that finished (decided or threw), or null when they are not
    /// recorded. Read only after such an outcome: a call past its deadline may still be drawing.
    /// </summary>
    public DebugRecorder? Drawings => _drawings;

    /// <summary>Records the strategy's debug drawings from the next call on.</summary>
    public void RecordDrawings() => _drawings ??= new DebugRecorder();

    /// <summary>What the last call that finished printed, or null when it is not recorded (read as <see cref="Drawings"/>).</summary>
    public StrategyLog? Log => _log;

    /// <summary>Records what the strategy prints from the next call on (the console must be routed: <see cref="ConsoleRouter.Install"/>).</summary>
    public void RecordLog() => _log ??= new StrategyLog();

    /// <summary>Lets the strategy's thread end once its current call (if any) returns; the runner is not used afterwards.</summary>
    public void Stop()
    {
        _stopped = true;
        _start.Release();
    }

    private void Loop()
    {
        while (true)
        {
            _start.Wait();
            if (_stopped)
            {
                return;
            }

            var drawings = _drawings;
            drawings?.Enter(_fish);
            var log = _log;
            log?.Clear();
            ConsoleRouter.Enter(log); // without a log, what it prints still reaches the console escaped

            _clock.CallStarting();
            try
            {
                _strategy.Decide(_snapshot!.Snapshot, _fish, _work);
            }
            catch (Exception e)
            {
                _error = e;
            }
            finally
            {
                if (drawings is not null)
                {
                    DebugRecorder.Exit();
                }

                ConsoleRouter.Exit();
            }

            (_cpu, _wall) = _clock.CallEnded();
            _done.Release();
        }
    }
}
