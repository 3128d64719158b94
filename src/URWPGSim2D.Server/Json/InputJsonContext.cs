using System.Text.Json.Serialization;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// Source-generated (reflection-free, trimming- and AOT-safe) System.Text.Json metadata for
/// reading input files. Strict JSON (no comments, no trailing commas), case-sensitive names,
/// unknown properties ignored. The strings "NaN", "Infinity" and "-Infinity" are accepted where
/// a number is expected, so that a non-finite value reaches the shape checks and is reported
/// by field ("must be a finite number, got NaN") rather than as a type error.
/// </summary>
[JsonSourceGenerationOptions(NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals)]
[JsonSerializable(typeof(PairDto[]))]
[JsonSerializable(typeof(ShapeDto[]))]
[JsonSerializable(typeof(QueryInputDto))]
internal sealed partial class InputJsonContext : JsonSerializerContext;
