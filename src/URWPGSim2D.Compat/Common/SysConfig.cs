using System.Xml;

namespace URWPGSim2D.Common;

/// <summary>
/// The original's configuration reader (its <c>config.xml</c>). Here it serves, from memory, the configuration the
/// original was deployed with: fish sizes (BodyLength 160, BodyWidth 45, TailJointLength1..3 88, 66, 55), BallRadius 58,
/// the field (FieldLengthXMm 3000, FieldLengthZMm 2000, GoalDepthMm 150, GoalWidthMm 400, ForbiddenZoneLengthXMm 400,
/// ForbiddenZoneLengthZMm 1000, CenterCircleRadiusMm 500, …), the display sizes, MaxCachedCycles 50 and the moving
/// obstacles of 2 vs 2. No file is read or written, and the values are the configured defaults, not the running
/// item's (read the match's through <see cref="Mission"/> and <see cref="Field.Instance"/>). The original's members
/// that return or add XML nodes (<c>GetXmlNode</c>, <c>AddXmlNode</c>, <c>AddXmElements</c>) are not offered.
/// </summary>
public class SysConfig
{
    private const string Deployed = """
        <config>
          <fish>
            <fishbody><BodyLength>160</BodyLength><BodyWidth>45</BodyWidth></fishbody>
            <fishtail><TailJointLength1>88</TailJointLength1><TailJointLength2>66</TailJointLength2><TailJointLength3>55</TailJointLength3></fishtail>
          </fish>
          <ball><BallRadius>58</BallRadius></ball>
          <obstacle />
          <form>
            <mainform><SpanBetweenFieldAndTabControlPix>10</SpanBetweenFieldAndTabControlPix><FormPaddingPix>10</FormPaddingPix></mainform>
            <showGameform><FormLocationX>11</FormLocationX><FormLocationY>102</FormLocationY><FormWidth>662</FormWidth><FormHighth>450</FormHighth></showGameform>
            <tabControl />
          </form>
          <field>
            <FieldLengthXMm>3000</FieldLengthXMm><FieldLengthZMm>2000</FieldLengthZMm><GoalDepthMm>150</GoalDepthMm><GoalWidthMm>400</GoalWidthMm>
            <FieldInnerBorderPix>5</FieldInnerBorderPix><FieldOuterBorderPix>20</FieldOuterBorderPix>
            <ForbiddenZoneLengthXMm>400</ForbiddenZoneLengthXMm><ForbiddenZoneLengthZMm>1000</ForbiddenZoneLengthZMm>
            <CenterCircleRadiusMm>500</CenterCircleRadiusMm><MovingCircleRadiusMm>80</MovingCircleRadiusMm>
            <OffsetHeightMm>1200</OffsetHeightMm><OffsetWidthMm>1900</OffsetWidthMm>
          </field>
          <paras><MaxCachedCycles>50</MaxCachedCycles></paras>
          <missions>
            <newmatch2v2>
              <dynamicRectangle1><LengthMm>174</LengthMm><WidthMm>58</WidthMm><DirectionDeg>0</DirectionDeg><VelocityMmPs>80</VelocityMmPs><VelocityDirectionRad>-1.5707963267949</VelocityDirectionRad><AngularVelocityRadPs>0</AngularVelocityRadPs><CircleTimes>101</CircleTimes></dynamicRectangle1>
              <dynamicRectangle2><LengthMm>174</LengthMm><WidthMm>58</WidthMm><DirectionDeg>0</DirectionDeg><VelocityMmPs>80</VelocityMmPs><VelocityDirectionRad>1.5707963267949</VelocityDirectionRad><AngularVelocityRadPs>0</AngularVelocityRadPs><CircleTimes>101</CircleTimes></dynamicRectangle2>
            </newmatch2v2>
          </missions>
        </config>
        """;

    private static readonly object Gate = new();
    private static SysConfig? _instance;
    private readonly XmlDocument _document = new();

    private SysConfig()
    {
        _document.LoadXml(Deployed);
    }

    /// <summary>The process's reader (made on first use, again after <see cref="release"/>).</summary>
    /// <returns>The one <see cref="SysConfig"/>.</returns>
    public static SysConfig Instance()
    {
        lock (Gate)
        {
            return _instance ??= new SysConfig();
        }
    }

    /// <summary>Drops the reader, so the next <see cref="Instance"/> makes a new one (the original reloaded its file).</summary>
    public static void release()
    {
        lock (Gate)
        {
            _instance = null;
        }
    }

    /// <summary>The text of the first element named <paramref name="strKeyName"/> in document order, as the original's reader.</summary>
    /// <param name="strKeyName">An element name, for example <c>BodyLength</c>.</param>
    /// <returns>Its text, for example <c>"160"</c>.</returns>
    /// <exception cref="InvalidOperationException">No element has that name (the original's reader failed too).</exception>
    public string MyXmlReader(string strKeyName)
    {
        ArgumentNullException.ThrowIfNull(strKeyName);
        lock (_document)
        {
            var list = _document.GetElementsByTagName(strKeyName);
            return list.Count > 0 ? list[0]!.InnerText : throw new InvalidOperationException("The configuration has no element " + strKeyName + ".");
        }
    }

    /// <summary>The text of the node an XPath selects, for example <c>/config/ball/BallRadius</c>.</summary>
    /// <param name="xpath">The XPath.</param>
    /// <returns>Its text.</returns>
    /// <exception cref="InvalidOperationException">No node matches (the original failed with a null reference).</exception>
    public string GetValue(string xpath)
    {
        ArgumentNullException.ThrowIfNull(xpath);
        lock (_document)
        {
            return _document.SelectSingleNode(xpath)?.InnerText ?? throw new InvalidOperationException("No configuration node matches " + xpath + ".");
        }
    }
}
