using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>Base of round moving objects (balls): radius, pose and speeds.</summary>
[Serializable]
public class RoundedDynamic : ICloneable
{
    /// <summary>Creates a round object of radius 58 mm.</summary>
    public RoundedDynamic()
    {
        SetRoundedDynamic();
    }

    /// <summary>Radius, mm.</summary>
    public int RadiusMm;

    /// <summary>Fill colour (display only).</summary>
    public Color ColorFilled;

    /// <summary>Border colour (display only).</summary>
    public Color ColorBorder;

    /// <summary>Border width, px (display only).</summary>
    public int BorderWidthPix;

    /// <summary>Centre, mm (Y = 0).</summary>
    public Xna.Vector3 PositionMm;

    /// <summary>Last cycle's centre (not given to strategies: zero).</summary>
    public Xna.Vector3 PrePositionMm;

    /// <summary>Speed, mm/s.</summary>
    public float VelocityMmPs;

    /// <summary>Last cycle's speed (not given to strategies: zero).</summary>
    public float PreVelocityMmPs;

    /// <summary>Direction of motion, rad from +X toward +Z.</summary>
    public float VelocityDirectionRad;

    /// <summary>Last cycle's direction (not given to strategies: zero).</summary>
    public float PreVelocityDirectionRad;

    /// <summary>Angular speed, rad/s.</summary>
    public float AngularVelocityRadPs;

    /// <summary>Last cycle's angular speed (not given to strategies: zero).</summary>
    public float PreAngularVelocityRadPs;

    /// <summary>This cycle's contact (not given to strategies).</summary>
    public CollisionType Collision;

    /// <summary>Last cycle's contact (not given to strategies).</summary>
    public CollisionType PreCollision;

    /// <summary>Sets the default radius (58 mm) and border.</summary>
    public void SetRoundedDynamic()
    {
        RadiusMm = 58;
        BorderWidthPix = 0;
    }

    /// <summary>Sets speeds back to rest.</summary>
    public void ResetSomeLocomotionPara()
    {
        VelocityMmPs = PreVelocityMmPs = 0f;
        VelocityDirectionRad = PreVelocityDirectionRad = 0f;
        AngularVelocityRadPs = PreAngularVelocityRadPs = 0f;
    }

    /// <summary>A copy of radius, border, centre and speeds.</summary>
    /// <returns>A new object of the same kind.</returns>
    public virtual object Clone()
    {
        var copy = new RoundedDynamic();
        CopyTo(copy);
        return copy;
    }

    /// <summary>Copies radius, border, centre and speeds onto <paramref name="target"/>.</summary>
    /// <param name="target">The object to overwrite.</param>
    public void CopyTo(RoundedDynamic target)
    {
        ArgumentNullException.ThrowIfNull(target);
        target.RadiusMm = RadiusMm;
        target.BorderWidthPix = BorderWidthPix;
        target.PositionMm = PositionMm;
        target.VelocityMmPs = VelocityMmPs;
        target.VelocityDirectionRad = VelocityDirectionRad;
        target.AngularVelocityRadPs = AngularVelocityRadPs;
    }
}
