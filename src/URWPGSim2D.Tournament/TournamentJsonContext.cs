using System.Text.Json.Serialization;

namespace URWPGSim2D.Tournament;

/// <summary>Source-generated JSON of the tournament's files (strings only: the files are written field by field).</summary>
[JsonSerializable(typeof(string))]
internal sealed partial class TournamentJsonContext : JsonSerializerContext;
