using System.IO;
using System.Reflection;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;

namespace URWPGSim2D.Ladder.Web;

/// <summary>
/// The pages: the ladders' overview, a ladder's standings (updating without reload) and queue
/// (<c>?ladder=ID</c>; without it, the only ladder), a team's page, a match's page with the replay
/// viewer, and the organiser's page. Each is static HTML with a script over the JSON API.
/// </summary>
internal static class LadderPages
{
    public static void Map(IEndpointRouteBuilder app)
    {
        app.MapGet("/", () => Page("standings.html"));
        app.MapGet("/teams/{name}", () => Page("team.html"));
        app.MapGet("/matches/{id}", () => Page("match.html"));
        app.MapGet("/queue", () => Page("queue.html"));
        app.MapGet("/ladders", () => Page("ladders.html"));
        app.MapGet("/organiser", () => Page("organiser.html"));
        app.MapGet("/ladder.js", () => Results.Text(Asset("ladder.js"), "text/javascript; charset=utf-8", null, 200));
        app.MapGet("/favicon.ico", () => Results.NoContent()); // no icon: asked by every browser, answered without an error
        app.MapGet("/ladder.css", () => Results.Text(Asset("ladder.css"), "text/css; charset=utf-8", null, 200));
    }

    private static IResult Page(string name) => Results.Text(Asset(name), "text/html; charset=utf-8", null, 200);

    private static string Asset(string name)
    {
        using var stream = typeof(LadderPages).Assembly.GetManifestResourceStream("URWPGSim2D.Ladder." + name)!;
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }
}
