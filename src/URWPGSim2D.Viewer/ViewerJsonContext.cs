using System.Text.Json.Serialization;

namespace URWPGSim2D.Viewer;

/// <summary>Source-generated JSON for the viewer's few serialised values (no reflection).</summary>
[JsonSerializable(typeof(string))]
internal sealed partial class ViewerJsonContext : JsonSerializerContext;
