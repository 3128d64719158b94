using System.Buffers;
using System.Text.Json;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The <c>collide</c> output document: one compact JSON array, one element per pair. A pair
/// without a fish is written as <see cref="CollisionResultDto"/> (exactly as before fish
/// existed); a pair with a fish as <see cref="FishCollisionResultDto"/> (the same four fields,
/// then <c>partA</c> and <c>partB</c>).
/// </summary>
internal static class CollideOutput
{
    /// <summary>Formats the answers.</summary>
    /// <param name="contacts">The contact of each pair, in input order.</param>
    /// <param name="withParts">For each pair, whether it involves a fish (then its parts are written).</param>
    /// <returns>The JSON text, without a trailing newline.</returns>
    public static string Format(FishContact[] contacts, bool[] withParts)
    {
        var buffer = new ArrayBufferWriter<byte>();
        using (var writer = new Utf8JsonWriter(buffer))
        {
            writer.WriteStartArray();
            for (int i = 0; i < contacts.Length; i++)
            {
                if (withParts[i])
                {
                    JsonSerializer.Serialize(writer, FishCollisionResultDto.From(contacts[i]), OutputJsonContext.Default.FishCollisionResultDto);
                }
                else
                {
                    JsonSerializer.Serialize(writer, CollisionResultDto.From(contacts[i].Result), OutputJsonContext.Default.CollisionResultDto);
                }
            }

            writer.WriteEndArray();
        }

        return Encoding.UTF8.GetString(buffer.WrittenSpan);
    }
}
