using System;
using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Pseudo-continuous collision detection over a world of bodies for one step of time: every
/// moving body moves linearly from its state at the start of the step (translation and turning;
/// a fish's joints keep their angles), and every contact is reported, in time order, at its time
/// of first contact through an <see cref="IContactHandler"/> that applies the caller's response.
/// Nothing is missed and nothing tunnels: each candidate pair (found by the broad phase, a
/// uniform grid by default) is sampled on its own clock, often enough that neither
/// body can pass through the other between two samples, and not at all while its bounding circles
/// are too far apart to meet. After the step no two bodies overlap by more than 0.5 mm: a body
/// whose response leaves it inside another one has its move rejected. The same bodies and calls
/// give the same contacts, bit for bit. After warm-up a step allocates nothing.
/// </summary>
/// <remarks>See docs/motion.md for the algorithm and a worked example.</remarks>
public sealed partial class Stepper
{
    private readonly SweepPlanner _planner;
    private readonly PairTable _table = new(0);
    private IContactHandler? _handler;

    /// <summary>Creates an empty stepper.</summary>
    /// <param name="broadPhase">The broad phase over the bodies' swept boxes; every kind gives the same contacts.</param>
    /// <exception cref="ArgumentException"><paramref name="broadPhase"/> is not a defined kind.</exception>
    public Stepper(BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid)
        : this(BroadPhaseFactory.Create(broadPhase, nameof(broadPhase)))
    {
    }

    /// <summary>Creates an empty stepper over a given broad phase instance (tests: a grid of a chosen cell size).</summary>
    /// <param name="broadPhase">The broad phase over the bodies' swept boxes.</param>
    internal Stepper(IBroadPhase broadPhase)
    {
        ArgumentNullException.ThrowIfNull(broadPhase);
        _planner = new SweepPlanner(broadPhase);
        _scheduler = new Scheduler(this);
    }

    /// <summary>The time within the current step (a fraction 0 … 1 of its duration): during a handler call, the contact's time.</summary>
    public double Time { get; private set; }

    /// <summary>Distinct sample times of the last step.</summary>
    public int SubSteps { get; private set; }

    /// <summary>Contact events (times of first contact) of the last step.</summary>
    public int Events { get; private set; }

    /// <summary>Bodies whose move was rejected in the last step (see <see cref="IContactHandler.OnMoveRejected"/>).</summary>
    public int RejectedMoves { get; private set; }

    /// <summary>Deepest overlap of any pair (walls included) at the end of the last step, mm.</summary>
    public float LeftoverOverlap { get; private set; }

    /// <summary>
    /// Moves every body through one step of <paramref name="seconds"/>, reporting each contact to
    /// <paramref name="handler"/> at its time of first contact, in time order.
    /// </summary>
    /// <param name="seconds">Duration of the step, s (positive and finite).</param>
    /// <param name="handler">The contact response.</param>
    /// <exception cref="ArgumentException"><paramref name="seconds"/> is not positive and finite.</exception>
    /// <exception cref="ArgumentNullException"><paramref name="handler"/> is null.</exception>
    public void Step(float seconds, IContactHandler handler)
    {
        Begin(seconds, handler);
        SampleIslands();
        for (double time; (time = NextTime()) >= 0.0;)
        {
            int due = _sampler.TakeDue(time, _table);
            _sampler.HitCount = 0;
            if (TakeHeld(time) + due > 0)
            {
                _sampler.MarkSampled(time);
                _sampler.SampleDue(time, _table, _bodies, seconds, this);
                HandleHits(time);
            }
        }

        SubSteps = _sampler.SampledTicks();
        MoveAllTo(1.0);
        float deepest = MathF.Max(_sampler.DeepestAtEnd, SettleTouched());
        LeftoverOverlap = RejectOverlapping(deepest);
        End();
    }

    // Every body starts the step at its current state; every pair is planned from time 0.
    private void Begin(float seconds, IContactHandler handler)
    {
        if (!(seconds > 0f) || float.IsPositiveInfinity(seconds))
        {
            throw new ArgumentException($"step duration must be positive and finite, got {seconds}", nameof(seconds));
        }

        ArgumentNullException.ThrowIfNull(handler);
        EnsureLoaded();
        _handler = handler;
        _planner.Seconds = seconds;
        SubSteps = 0;
        Events = 0;
        RejectedMoves = 0;
        Time = 0.0;
        _stepping = true;
        foreach (Body body in _planner.MoverBodies)
        {
            body.Rebase(0.0);
            body.KeepStepStart();
            body.Events = 0;
            body.EventsInPlace = 0;
            body.LastEventTime = -1.0;
        }

        _table.Clear();
        _sampler.BeginStep();
        _touched.Clear();
        _deferred.Clear();
        _scheduler.Settling = false;
        _recorder ??= new Recorder(this);
        _planner.PlanAll(0.0, _recorder);
    }

    // The step's end state becomes the state a rejected move of the next step goes back to.
    private void End()
    {
        _stepping = false;
        Time = 0.0;
        foreach (Body body in _planner.MoverBodies)
        {
            body.Rebase(0.0);
            Remember(body);
        }

        _handler = null;
    }
}
