using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// A fish's pose as a strategy can best know it. The view's position (±30 mm per axis) and heading
/// (±5°) are noisy, but its speed and turn rate are exact, so each cycle the pose is carried forward
/// by the cycle's motion and then pulled toward the view by a Kalman gain per quantity: the
/// uncertainty grows by the reference's motion noise of the cycle (heading ±v²/500000 rad, position
/// ±30·|ω| mm, plus a little for contacts) and shrinks with every view. A view more than 150 mm
/// from the estimate (a fish placed by the referee) restarts it. One value per fish, kept across cycles.
/// </summary>
internal struct FishTrack
{
    // Variances of one view: uniform ±30 mm per axis and ±5° of heading.
    private const float ViewPositionVariance = 30f * 30f / 3f;
    private const float ViewHeadingVariance = 0.0872665f * 0.0872665f / 3f;
    private const float Dt = 0.1f;

    private float _positionVariance;
    private float _headingVariance;

    /// <summary>The estimated body centre, mm.</summary>
    public Vector2 Position;

    /// <summary>The estimated heading, rad.</summary>
    public float Heading;

    /// <summary>Whether the track has seen the fish.</summary>
    public bool Started;

    /// <summary>Unit vector of the estimated heading.</summary>
    public readonly Vector2 Forward => new(MathF.Cos(Heading), MathF.Sin(Heading));

    /// <summary>Takes this cycle's view of the fish.</summary>
    public void Update(in FishView view)
    {
        if (!Started || Vector2.Distance(view.Position, Position) > 150f)
        {
            Position = view.Position;
            Heading = view.Heading;
            _positionVariance = ViewPositionVariance;
            _headingVariance = ViewHeadingVariance;
            Started = true;
            return;
        }

        // The last cycle's motion: the view's speed and turn rate are the ones it was made with.
        float turned = view.AngularSpeed * Dt;
        float middle = Heading + (turned * 0.5f);
        Position += new Vector2(MathF.Cos(middle), MathF.Sin(middle)) * (view.Speed * Dt);
        Heading = Angle.Wrap(Heading + turned);

        float headingNoise = view.Speed * view.Speed / 500000f;
        float positionNoise = 30f * MathF.Abs(view.AngularSpeed);
        _headingVariance += (headingNoise * headingNoise / 3f) + 1e-5f;
        _positionVariance += (positionNoise * positionNoise / 3f) + 4f;

        float headingGain = _headingVariance / (_headingVariance + ViewHeadingVariance);
        Heading = Angle.Wrap(Heading + (headingGain * Angle.Wrap(view.Heading - Heading)));
        _headingVariance *= 1f - headingGain;

        float positionGain = _positionVariance / (_positionVariance + ViewPositionVariance);
        Position += positionGain * (view.Position - Position);
        _positionVariance *= 1f - positionGain;
    }
}
