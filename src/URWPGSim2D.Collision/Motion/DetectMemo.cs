using System;
using System.Numerics;
using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The last few exact tests of one body (as A) against its partners, with the poses they were
/// computed at: a test repeated at the same poses (the stepper and the contact response often test
/// a pair again before anything moved: the probe that found the time of first contact and the
/// response, the response's final check and the re-planning after it, settling) is answered
/// without testing again. A pose is everything the test reads: position, heading, a fish's joints
/// and the pose its model was built at, compared bit for bit; an entry is written with the poses
/// after the test (a test may rebuild a fish's model), so a hit means the test would rebuild
/// nothing and compute exactly the stored answer.
/// </summary>
internal sealed class DetectMemo
{
    private const int Entries = 4;
    private readonly Entry[] _entries = new Entry[Entries];
    private int _next;

    /// <summary>The stored test of A against B at their current poses, if any.</summary>
    public bool TryGet(Body a, Body b, out Hit hit)
    {
        PoseKey ka = PoseKey.Of(a), kb = PoseKey.Of(b);
        foreach (ref readonly Entry e in _entries.AsSpan())
        {
            if (e.Partner == b.Id + 1 && e.A.Equals(ka) && e.B.Equals(kb))
            {
                hit = e.Hit;
                return true;
            }
        }

        hit = default;
        return false;
    }

    /// <summary>Stores a test of A against B at their current poses (replacing that partner's entry, else the oldest).</summary>
    public void Store(Body a, Body b, in Hit hit)
    {
        int slot = -1;
        for (int i = 0; i < Entries; i++)
        {
            if (_entries[i].Partner == b.Id + 1)
            {
                slot = i;
                break;
            }
        }

        if (slot < 0)
        {
            slot = _next;
            _next = (_next + 1) % Entries;
        }

        _entries[slot] = new Entry { Partner = b.Id + 1, A = PoseKey.Of(a), B = PoseKey.Of(b), Hit = hit };
    }

    private struct Entry
    {
        public int Partner; // partner id + 1 (0: empty)
        public PoseKey A;
        public PoseKey B;
        public Hit Hit;
    }

    // Everything a test reads of a body that can change: pose, joints, and a fish model's pose and joints.
    [StructLayout(LayoutKind.Sequential)]
    private struct PoseKey
    {
        public Vector2 Position;
        public float Heading;
        public float Joint1, Joint2, Joint3;
        public Vector2 ModelPosition;
        public float ModelHeading;
        public float ModelJoint1, ModelJoint2, ModelJoint3;

        public static PoseKey Of(Body body)
        {
            var key = new PoseKey { Position = body.Position, Heading = body.Heading };
            if (body.Model is { } model)
            {
                var pose = model.Pose;
                key.Joint1 = body.Joint1;
                key.Joint2 = body.Joint2;
                key.Joint3 = body.Joint3;
                key.ModelPosition = pose.Position;
                key.ModelHeading = pose.Heading;
                key.ModelJoint1 = pose.Joint1;
                key.ModelJoint2 = pose.Joint2;
                key.ModelJoint3 = pose.Joint3;
            }

            return key;
        }

        // Bit for bit (−0 is not +0, a NaN equals itself).
        public readonly bool Equals(in PoseKey other) =>
            MemoryMarshal.AsBytes(new ReadOnlySpan<PoseKey>(in this)).SequenceEqual(MemoryMarshal.AsBytes(new ReadOnlySpan<PoseKey>(in other)));
    }
}
