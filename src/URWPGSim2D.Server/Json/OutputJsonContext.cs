using System.Text.Json.Serialization;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// Source-generated (reflection-free, trimming- and AOT-safe) System.Text.Json metadata for
/// writing results: compact (no indentation), numbers in shortest round-trip single-precision
/// form, null properties omitted. Named non-finite literals are not allowed: a NaN in a result
/// would be a bug and fails loudly instead of being written.
/// </summary>
[JsonSourceGenerationOptions(WriteIndented = false, DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull)]
[JsonSerializable(typeof(CollisionResultDto[]))]
[JsonSerializable(typeof(FishCollisionResultDto))]
[JsonSerializable(typeof(ShapePiecesDto[]))]
internal sealed partial class OutputJsonContext : JsonSerializerContext;
