using System.Buffers.Binary;

namespace URWPGSim2D.Protocol;

/// <summary>
/// The packed form of a <c>cycle</c> message's fish and balls (docs/protocol.md, "Packed cycles"), for a
/// client that asks for it in its hello: every value's bits, little-endian, in a fixed order, so a
/// cycle costs a copy instead of a hundred numbers formatted and parsed. Per fish
/// (<see cref="FishBytes"/>): index and team (int32); position x and y, heading, speed, angular speed,
/// body, head length, width, the three joint angles, the three tail lengths (float32); the decision's
/// VCode and TCode (int32). Per ball (<see cref="BallBytes"/>): index (int32); position x and y, velocity
/// x and y, radius (float32). The fish first, then the balls, in the snapshot's order.
/// </summary>
internal static class PackedCycle
{
    /// <summary>Bytes of one fish.</summary>
    public const int FishBytes = 72;

    /// <summary>Bytes of one ball.</summary>
    public const int BallBytes = 24;

    /// <summary>Bytes of <paramref name="fish"/> fish and <paramref name="balls"/> balls.</summary>
    public static int Length(int fish, int balls) => (fish * FishBytes) + (balls * BallBytes);

    /// <summary>Writes the fish and balls of <paramref name="s"/> into <paramref name="to"/> (at least <see cref="Length"/> bytes).</summary>
    public static void Write(MatchSnapshot s, Span<byte> to)
    {
        ArgumentNullException.ThrowIfNull(s);
        int at = 0;
        foreach (ref readonly var f in s.Fish)
        {
            var b = to.Slice(at, FishBytes);
            BinaryPrimitives.WriteInt32LittleEndian(b, f.Index);
            BinaryPrimitives.WriteInt32LittleEndian(b[4..], f.Team);
            BinaryPrimitives.WriteSingleLittleEndian(b[8..], f.Position.X);
            BinaryPrimitives.WriteSingleLittleEndian(b[12..], f.Position.Y);
            BinaryPrimitives.WriteSingleLittleEndian(b[16..], f.Heading);
            BinaryPrimitives.WriteSingleLittleEndian(b[20..], f.Speed);
            BinaryPrimitives.WriteSingleLittleEndian(b[24..], f.AngularSpeed);
            BinaryPrimitives.WriteSingleLittleEndian(b[28..], f.BodyLength);
            BinaryPrimitives.WriteSingleLittleEndian(b[32..], f.HeadLength);
            BinaryPrimitives.WriteSingleLittleEndian(b[36..], f.Width);
            BinaryPrimitives.WriteSingleLittleEndian(b[40..], f.Joint1);
            BinaryPrimitives.WriteSingleLittleEndian(b[44..], f.Joint2);
            BinaryPrimitives.WriteSingleLittleEndian(b[48..], f.Joint3);
            BinaryPrimitives.WriteSingleLittleEndian(b[52..], f.TailLength1);
            BinaryPrimitives.WriteSingleLittleEndian(b[56..], f.TailLength2);
            BinaryPrimitives.WriteSingleLittleEndian(b[60..], f.TailLength3);
            BinaryPrimitives.WriteInt32LittleEndian(b[64..], f.Decision.VCode);
            BinaryPrimitives.WriteInt32LittleEndian(b[68..], f.Decision.TCode);
            at += FishBytes;
        }

        foreach (ref readonly var ball in s.Balls)
        {
            var b = to.Slice(at, BallBytes);
            BinaryPrimitives.WriteInt32LittleEndian(b, ball.Index);
            BinaryPrimitives.WriteSingleLittleEndian(b[4..], ball.Position.X);
            BinaryPrimitives.WriteSingleLittleEndian(b[8..], ball.Position.Y);
            BinaryPrimitives.WriteSingleLittleEndian(b[12..], ball.Velocity.X);
            BinaryPrimitives.WriteSingleLittleEndian(b[16..], ball.Velocity.Y);
            BinaryPrimitives.WriteSingleLittleEndian(b[20..], ball.Radius);
            at += BallBytes;
        }
    }

    /// <summary>Reads <paramref name="from"/> into <paramref name="fish"/> and <paramref name="balls"/>, whose lengths it must match exactly.</summary>
    /// <exception cref="ProtocolException">It holds another number of bytes.</exception>
    public static void Read(ReadOnlySpan<byte> from, Span<FishView> fish, Span<BallView> balls)
    {
        int length = Length(fish.Length, balls.Length);
        if (from.Length != length)
        {
            throw new ProtocolException($"packed: {from.Length} bytes, the assignment's {fish.Length} fish and {balls.Length} balls take {length}");
        }

        int at = 0;
        for (int i = 0; i < fish.Length; i++)
        {
            var b = from.Slice(at, FishBytes);
            fish[i] = new FishView(
                BinaryPrimitives.ReadInt32LittleEndian(b),
                BinaryPrimitives.ReadInt32LittleEndian(b[4..]),
                new Vector2(BinaryPrimitives.ReadSingleLittleEndian(b[8..]), BinaryPrimitives.ReadSingleLittleEndian(b[12..])),
                BinaryPrimitives.ReadSingleLittleEndian(b[16..]),
                BinaryPrimitives.ReadSingleLittleEndian(b[20..]),
                BinaryPrimitives.ReadSingleLittleEndian(b[24..]),
                BinaryPrimitives.ReadSingleLittleEndian(b[28..]),
                BinaryPrimitives.ReadSingleLittleEndian(b[32..]),
                new Decision(BinaryPrimitives.ReadInt32LittleEndian(b[64..]), BinaryPrimitives.ReadInt32LittleEndian(b[68..])))
            {
                Width = BinaryPrimitives.ReadSingleLittleEndian(b[36..]),
                Joint1 = BinaryPrimitives.ReadSingleLittleEndian(b[40..]),
                Joint2 = BinaryPrimitives.ReadSingleLittleEndian(b[44..]),
                Joint3 = BinaryPrimitives.ReadSingleLittleEndian(b[48..]),
                TailLength1 = BinaryPrimitives.ReadSingleLittleEndian(b[52..]),
                TailLength2 = BinaryPrimitives.ReadSingleLittleEndian(b[56..]),
                TailLength3 = BinaryPrimitives.ReadSingleLittleEndian(b[60..]),
            };
            at += FishBytes;
        }

        for (int i = 0; i < balls.Length; i++)
        {
            var b = from.Slice(at, BallBytes);
            balls[i] = new BallView(
                BinaryPrimitives.ReadInt32LittleEndian(b),
                new Vector2(BinaryPrimitives.ReadSingleLittleEndian(b[4..]), BinaryPrimitives.ReadSingleLittleEndian(b[8..])),
                new Vector2(BinaryPrimitives.ReadSingleLittleEndian(b[12..]), BinaryPrimitives.ReadSingleLittleEndian(b[16..])),
                BinaryPrimitives.ReadSingleLittleEndian(b[20..]));
            at += BallBytes;
        }
    }
}
