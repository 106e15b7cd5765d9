var ou="fleetlink.token",au="fleetlink.principal",Si={token(){return sessionStorage.getItem(ou)},principal(){return sessionStorage.getItem(au)},set(n,e){sessionStorage.setItem(ou,n),sessionStorage.setItem(au,e)},clear(){sessionStorage.removeItem(ou),sessionStorage.removeItem(au)},wsUrl(){let n=location.protocol==="https:"?"wss:":"ws:",e=this.token();return`${n}//${location.host}/${e?`?token=${encodeURIComponent(e)}`:""}`}};var dr=class extends Error{constructor(t,i){super(i);this.status=t}status};async function gn(n,e={}){let t=new Headers(e.headers),i=Si.token();i&&t.set("Authorization",`Bearer ${i}`),e.body&&t.set("Content-Type","application/json");let s=await fetch(n,{...e,headers:t,cache:"no-store"}),r=await s.text(),o=null;try{o=r?JSON.parse(r):null}catch{o=r}if(!s.ok)throw new dr(s.status,o&&o.error||r||`HTTP ${s.status}`);return o}var It={frames:{},poses:{},feedback:[],lastResult:null,lastServiceResponse:null,disabled:{},renders:0,cloudAgesMs:[],busyMs:{decode:0,cloudUnpack:0,cloudRender:0},markers:{drawn:0,shapes:0,byType:{},byNs:{}},mapToScreen:null,config:{loaded:!1,mayChange:!1,overlay:null,result:""}};function Jn(n){It.frames[n]=(It.frames[n]??0)+1}globalThis.fleetlink=It;var ve={POS_INT:0,NEG_INT:1,BYTE_STRING:2,UTF8_STRING:3,ARRAY:4,MAP:5,TAG:6,SIMPLE_FLOAT:7},Mt={DATE_STRING:0,DATE_EPOCH:1,POS_BIGINT:2,NEG_BIGINT:3,DECIMAL_FRAC:4,BIGFLOAT:5,BASE64URL_EXPECTED:21,BASE64_EXPECTED:22,BASE16_EXPECTED:23,CBOR:24,URI:32,BASE64URL:33,BASE64:34,MIME:36,DATE_EPOCH_DAYS:100,SET:258,JSON:262,WTF8:273,SYMBOL:280,DATE_FULL:1004,REGEXP:21066,SELF_DESCRIBED:55799,INVALID_16:65535,INVALID_32:4294967295,INVALID_64:0xffffffffffffffffn},ht={ZERO:0,ONE:24,TWO:25,FOUR:26,EIGHT:27,INDEFINITE:31},Ki={FALSE:20,TRUE:21,NULL:22,UNDEFINED:23},Jt=class{static BREAK=Symbol.for("github.com/hildjj/cbor2/break");static ENCODED=Symbol.for("github.com/hildjj/cbor2/cbor-encoded");static LENGTH=Symbol.for("github.com/hildjj/cbor2/length")},Yr={MIN:-(2n**63n),MAX:2n**64n-1n};var nt=class n{static#e=new Map;tag;contents;constructor(e,t=void 0){this.tag=e,this.contents=t}get noChildren(){return!!n.#e.get(this.tag)?.noChildren}static registerDecoder(e,t,i){let s=this.#e.get(e);return this.#e.set(e,t),s&&("comment"in t||(t.comment=s.comment),"noChildren"in t||(t.noChildren=s.noChildren)),i&&!t.comment&&(t.comment=()=>`(${i})`),s}static clearDecoder(e){let t=this.#e.get(e);return this.#e.delete(e),t}static getDecoder(e){return this.#e.get(e)}static getAllDecoders(){return new Map(this.#e)}*[Symbol.iterator](){yield this.contents}push(e){return this.contents=e,1}decode(e){let t=e?.tags?.get(this.tag)??(e?.ignoreGlobalTags?void 0:n.#e.get(this.tag));return t?t(this,e):this}comment(e,t){let i=e?.tags?.get(this.tag)??(e?.ignoreGlobalTags?void 0:n.#e.get(this.tag));if(i?.comment)return i.comment(this,e,t)}toCBOR(){return[this.tag,this.contents]}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return`${this.tag}(${i(this.contents,t)})`}};function Os(n){if(n!=null&&typeof n=="object")return n[Jt.ENCODED]}function np(n){if(n!=null&&typeof n=="object")return n[Jt.LENGTH]}function Fs(n,e){Object.defineProperty(n,Jt.ENCODED,{configurable:!0,enumerable:!1,value:e})}function Bs(n,e){let t=Object(n);return Fs(t,e),t}var lu=Symbol("CBOR_RANGES");function ip(n,e){Object.defineProperty(n,lu,{configurable:!1,enumerable:!1,writable:!1,value:e})}function Ko(n){return n[lu]}function H_(n){return Ko(n)!==void 0}function Jo(n,e=0,t=n.length-1){let i=n.subarray(e,t),s=Ko(n);if(s){let r=[];for(let o of s)if(o[0]>=e&&o[0]+o[1]<=t){let a=[...o];a[0]-=e,r.push(a)}r.length&&ip(i,r)}return i}function ll(n){let e=Math.ceil(n.length/2),t=new Uint8Array(e);e--;for(let i=n.length,s=i-2;i>=0;i=s,s-=2,e--)t[e]=parseInt(n.substring(s,i),16);return t}function On(n){return n.reduce((e,t)=>e+t.toString(16).padStart(2,"0"),"")}function sp(n){let e=n.reduce((o,a)=>o+a.length,0),t=n.some(o=>H_(o)),i=[],s=new Uint8Array(e),r=0;for(let o of n){if(!(o instanceof Uint8Array))throw new TypeError(`Invalid array: ${o}`);if(s.set(o,r),t){let a=o[lu]??[[0,o.length]];for(let l of a)l[0]+=r;i.push(...a)}r+=o.length}return t&&ip(s,i),s}function jo(n){let e=atob(n);return Uint8Array.from(e,t=>t.codePointAt(0))}var V_={"-":"+",_:"/"};function rp(n){let e=n.replace(/[_-]/g,t=>V_[t]);return jo(e.padEnd(Math.ceil(e.length/4)*4,"="))}function op(){let n=new Uint8Array(4),e=new Uint32Array(n.buffer);return!((e[0]=1)&n[0])}function cu(n){let e="";for(let t of n){let i=t.codePointAt(0)?.toString(16).padStart(4,"0");e&&(e+=", "),e+=`U+${i}`}return e}var Qo=class{#e=new Map;registerEncoder(e,t){let i=this.#e.get(e);return this.#e.set(e,t),i}get(e){return this.#e.get(e)}delete(e){return this.#e.delete(e)}clear(){this.#e.clear()}};function cl(n,e){let[t,i,s]=n,[r,o,a]=e,l=Math.min(s.length,a.length);for(let c=0;c<l;c++){let h=s[c]-a[c];if(h!==0)return h}return 0}var Zr=class n{static defaultOptions={chunkSize:4096};#e;#t=[];#n=null;#i=0;#s=0;constructor(e={}){if(this.#e={...n.defaultOptions,...e},this.#e.chunkSize<8)throw new RangeError(`Expected size >= 8, got ${this.#e.chunkSize}`);this.#r()}get length(){return this.#s}read(){this.#l();let e=new Uint8Array(this.#s),t=0;for(let i of this.#t)e.set(i,t),t+=i.length;return this.#r(),e}write(e){let t=e.length;t>this.#c()?(this.#l(),t>this.#e.chunkSize?(this.#t.push(e),this.#r()):(this.#r(),this.#t[this.#t.length-1].set(e),this.#i=t)):(this.#t[this.#t.length-1].set(e,this.#i),this.#i+=t),this.#s+=t}writeUint8(e){this.#o(1),this.#n.setUint8(this.#i,e),this.#a(1)}writeUint16(e,t=!1){this.#o(2),this.#n.setUint16(this.#i,e,t),this.#a(2)}writeUint32(e,t=!1){this.#o(4),this.#n.setUint32(this.#i,e,t),this.#a(4)}writeBigUint64(e,t=!1){this.#o(8),this.#n.setBigUint64(this.#i,e,t),this.#a(8)}writeInt16(e,t=!1){this.#o(2),this.#n.setInt16(this.#i,e,t),this.#a(2)}writeInt32(e,t=!1){this.#o(4),this.#n.setInt32(this.#i,e,t),this.#a(4)}writeBigInt64(e,t=!1){this.#o(8),this.#n.setBigInt64(this.#i,e,t),this.#a(8)}writeFloat32(e,t=!1){this.#o(4),this.#n.setFloat32(this.#i,e,t),this.#a(4)}writeFloat64(e,t=!1){this.#o(8),this.#n.setFloat64(this.#i,e,t),this.#a(8)}clear(){this.#s=0,this.#t=[],this.#r()}#r(){let e=new Uint8Array(this.#e.chunkSize);this.#t.push(e),this.#i=0,this.#n=new DataView(e.buffer,e.byteOffset,e.byteLength)}#l(){if(this.#i===0){this.#t.pop();return}let e=this.#t.length-1;this.#t[e]=this.#t[e].subarray(0,this.#i),this.#i=0,this.#n=null}#c(){let e=this.#t.length-1;return this.#t[e].length-this.#i}#o(e){this.#c()<e&&(this.#l(),this.#r())}#a(e){this.#i+=e,this.#s+=e}};var hu=1n<<15n,ea=0b11111n<<10n,dp=1n<<9n,pp=dp-1n,ap=dp|pp,uu=1n<<31n,ta=0b11111111n<<23n,mp=1n<<22n,gp=mp-1n,lp=mp|gp,hl=1n<<63n,fs=0b11111111111n<<52n,na=1n<<51n,ul=na-1n,cp=na|ul,hp=ul-(pp<<42n),up=ul-(gp<<29n),W_={2:"0b",8:"0o",16:"0x"},_p=(n=>(n[n.NATURAL=-2]="NATURAL",n[n.UNKNOWN=-1]="UNKNOWN",n[n.F16=2]="F16",n[n.F32=4]="F32",n[n.F64=8]="F64",n))(_p||{});function fp(n,e,t,i){let s="nan'";return n.quiet||(s+="!"),n.sign===-1&&(s+="-"),s+=i(Math.abs(n.payload),t),s+="'",s+=n.encodingIndicator,s}var ia=class extends Number{#e;#t=-1;constructor(e,t=!0,i=-1){super(NaN);let s=e;if(typeof e=="number"){if(!Number.isSafeInteger(e))throw new Error(`Invalid NAN payload: ${e}`);e=BigInt(e);let r=0n;if(e<0&&(r=hl,e=-e),e>=na)throw new Error(`Payload too large: ${s}`);let o=t?na:0n;switch(this.#e=r|fs|o|e,i){case-2:throw new Error("NAN_SIZE.NATURAL only valid for bigint constructor");case-1:i=this.preferredSize;break;case 2:if(this.#e&hp)throw new Error("Invalid size for payload");break;case 4:if(this.#e&up)throw new Error("Invalid size for payload");break;case 8:break;default:throw new Error(`Invalid size: ${i}`)}this.#t=i}else if(typeof e=="bigint"){let r=-1;if((e&fs)===fs)this.#e=e,r=8;else if((e&ta)===ta){let o=(e&uu)<<32n;this.#e=o|fs|(e&lp)<<29n,r=4}else if((e&ea)===ea){let o=(e&hu)<<48n;this.#e=o|fs|(e&ap)<<42n,r=2}else throw new Error(`Invalid raw NaN value: ${e}`);if(i===-1)this.#t=this.preferredSize;else if(i===-2)this.#t=r;else{if(i<r)throw new Error("Invalid bigint NaN size");this.#t=i}}else{let r=new DataView(e.buffer,e.byteOffset,e.byteLength);switch(e.length){case 3:{if(e[0]!==249)throw new Error("Invalid CBOR encoding for half float");let o=BigInt(r.getUint16(1,!1));if((o&ea)!==ea)throw new Error("Not a NaN");let a=(o&hu)<<48n;this.#e=a|fs|(o&ap)<<42n,this.#t=2;break}case 5:{if(e[0]!==250)throw new Error("Invalid CBOR encoding for single float");let o=BigInt(r.getUint32(1,!1));if((o&ta)!==ta)throw new Error("Not a NaN");let a=(o&uu)<<32n;this.#e=a|fs|(o&lp)<<29n,this.#t=4;break}case 9:{if(e[0]!==251)throw new Error("Invalid CBOR encoding for double float");if(this.#e=r.getBigUint64(1,!1),(this.#e&fs)!==fs)throw new Error("Not a NaN (NaNaN)");this.#t=8;break}default:throw new RangeError(`Invalid NAN size (should be 2, 4, or 8): ${e.length-1}`)}}if(!this.payload&&!this.quiet)throw new Error("Signalling NaN with zero payload")}get bytes(){let e=new ArrayBuffer(this.#t+1),t=new DataView(e);switch(this.#t){case 2:{t.setUint8(0,249);let i=(this.#e&hl?hu:0n)|ea|(this.#e&cp)>>42n;t.setUint16(1,Number(i),!1);break}case 4:{t.setUint8(0,250);let i=(this.#e&hl?uu:0n)|ta|(this.#e&cp)>>29n;t.setUint32(1,Number(i),!1);break}case 8:t.setUint8(0,251),t.setBigUint64(1,this.#e);break}return new Uint8Array(e)}get quiet(){return!!(this.#e&na)}get sign(){return this.#e&hl?-1:1}get payload(){return Number(this.#e&ul)*this.sign}get raw(){return this.#e}get encodingIndicator(){switch(this.#t){case 2:return"_1";case 4:return"_2"}return"_3"}get size(){return this.#t}get preferredSize(){return(this.#e&hp)===0n?2:(this.#e&up)===0n?4:8}get isShortestEncoding(){return this.preferredSize===this.#t}toCBOR(e){e.write(this.bytes)}toString(e=10){return fp(this,1,{},t=>(W_[e]??"")+t.toString(e))}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return fp(this,e,t,i)}};function fu(n,e=0,t=!1){let i=n[e]&128?-1:1,s=(n[e]&124)>>2,r=(n[e]&3)<<8|n[e+1];if(s===0){if(t&&r!==0)throw new Error(`Unwanted subnormal: ${i*5960464477539063e-23*r}`);return i*5960464477539063e-23*r}else if(s===31)return r?NaN:i*(1/0);return i*2**(s-25)*(1024+r)}function fl(n){let e=new DataView(new ArrayBuffer(4));e.setFloat32(0,n,!1);let t=e.getUint32(0,!1);if((t&8191)!==0)return null;let i=t>>16&32768,s=t>>23&255,r=t&8388607;if(!(s===0&&r===0))if(s>=113&&s<=142)i+=(s-112<<10)+(r>>13);else if(s>=103&&s<113){if(r&(1<<126-s)-1)return null;i+=r+8388608>>126-s}else if(s===255)i|=31744,i|=r>>13;else return null;return i}function yp(n){if(n!==0){let e=new ArrayBuffer(8),t=new DataView(e);t.setFloat64(0,n,!1);let i=t.getBigUint64(0,!1);if((i&0x7ff0000000000000n)===0n)return i&0x8000000000000000n?-0:0}return n}function xp(n){switch(n.length){case 2:fu(n,0,!0);break;case 4:{let e=new DataView(n.buffer,n.byteOffset,n.byteLength),t=e.getUint32(0,!1);if((t&2139095040)===0&&t&8388607)throw new Error(`Unwanted subnormal: ${e.getFloat32(0,!1)}`);break}case 8:{let e=new DataView(n.buffer,n.byteOffset,n.byteLength),t=e.getBigUint64(0,!1);if((t&0x7ff0000000000000n)===0n&&t&0x000fffffffffffn)throw new Error(`Unwanted subnormal: ${e.getFloat64(0,!1)}`);break}default:throw new TypeError(`Bad input to isSubnormal: ${n}`)}}var sa=class extends TypeError{code="ERR_ENCODING_INVALID_ENCODED_DATA";constructor(){super("The encoded data was not valid for encoding wtf-8")}},dl=class extends RangeError{code="ERR_ENCODING_NOT_SUPPORTED";constructor(e){super(`Invalid encoding: "${e}"`)}};var pl=new Uint8Array(0);var du=55296,vp=56320,bp=65533,ml="wtf-8";function $_(n){return n&&typeof n=="object"&&!(n instanceof ArrayBuffer)&&!(n instanceof SharedArrayBuffer)&&n.buffer instanceof ArrayBuffer}function q_(n){return n?n instanceof Uint8Array?n:$_(n)?new Uint8Array(n.buffer,n.byteOffset,n.byteLength):new Uint8Array(n):pl}var Y_=[0,0,0,0,0,0,0,0,-1,-1,-1,-1,1,1,2,3],pr=class n{static DEFAULT_BUFFERSIZE=4096;encoding=ml;fatal;ignoreBOM;bufferSize;#e=0;#t=0;#n=0;#i=!0;#s;constructor(e="wtf8",t=void 0){if(e.toLowerCase().replace("-","")!=="wtf8")throw new dl(e);if(this.fatal=!!t?.fatal,this.ignoreBOM=!!t?.ignoreBOM,this.bufferSize=Math.floor(t?.bufferSize??n.DEFAULT_BUFFERSIZE),isNaN(this.bufferSize)||this.bufferSize<1)throw new RangeError(`Invalid buffer size: ${t?.bufferSize}`);this.#s=new Uint16Array(this.bufferSize)}decode(e,t){let i=!!t?.stream,s=q_(e),r=[],o=this.#s,a=this.bufferSize-3,l=0,c=()=>{if(this.#t=0,this.#e=0,this.#n=0,this.fatal)throw new sa;o[l++]=bp},h=()=>{let u=this.#n;for(let m=0;m<u;m++)c()},f=u=>{if(this.#e===0)switch(Y_[u>>4]){case-1:c();break;case 0:o[l++]=u;break;case 1:this.#t=u&31,(this.#t&30)===0?c():(this.#e=1,this.#n=1);break;case 2:this.#t=u&15,this.#e=2,this.#n=1;break;case 3:u&8?c():(this.#t=u&7,this.#e=3,this.#n=1);break}else{if((u&192)!==128||this.#n===1&&this.#e===2&&this.#t===0&&(u&32)===0||this.#e===3&&this.#t===0&&(u&48)===0)return h(),f(u);if(this.#t=this.#t<<6|u&63,this.#n++,--this.#e===0){if(this.ignoreBOM||!this.#i||this.#t!==65279)if(this.#t<65536)o[l++]=this.#t;else{let m=this.#t-65536;o[l++]=m>>>10&1023|du,o[l++]=m&1023|vp}this.#t=0,this.#n=0,this.#i=!1}}};for(let u of s)l>=a&&(r.push(String.fromCharCode.apply(null,o.subarray(0,l))),l=0),f(u);return i||(this.#i=!0,(this.#t||this.#e)&&h()),l>0&&r.push(String.fromCharCode.apply(null,o.subarray(0,l))),r.join("")}};function Z_(n){let e=0;for(let t of n){let i=t.codePointAt(0);i<128?e++:i<2048?e+=2:i<65536?e+=3:e+=4}return e}var Kr=class{encoding=ml;encode(e){if(!e)return pl;let t=new Uint8Array(Z_(String(e)));return this.encodeInto(e,t),t}encodeInto(e,t){let i=String(e),s=i.length,r=t.length,o=0,a=0;for(a=0;a<s;a++){let l=i.codePointAt(a);if(l<128){if(o>=r)break;t[o++]=l}else if(l<2048){if(o>=r-1)break;t[o++]=192|l>>6,t[o++]=128|l&63}else if(l<65536){if(o>=r-2)break;t[o++]=224|l>>12,t[o++]=128|l>>6&63,t[o++]=128|l&63}else{if(o>=r-3)break;t[o++]=240|l>>18,t[o++]=128|l>>12&63,t[o++]=128|l>>6&63,t[o++]=128|l&63,a++}}return{read:a,written:o}}};var{ENCODED:o1}=Jt,Sp=ve.SIMPLE_FLOAT<<5|ht.TWO,K_=ve.SIMPLE_FLOAT<<5|ht.FOUR,J_=ve.SIMPLE_FLOAT<<5|ht.EIGHT,j_=ve.SIMPLE_FLOAT<<5|Ki.TRUE,Q_=ve.SIMPLE_FLOAT<<5|Ki.FALSE,ey=ve.SIMPLE_FLOAT<<5|Ki.UNDEFINED,ty=ve.SIMPLE_FLOAT<<5|Ki.NULL,ny=new TextEncoder,iy=new Kr,_l={...Zr.defaultOptions,avoidInts:!1,cde:!1,collapseBigInts:!0,dateTag:Mt.DATE_EPOCH,dcbor:!1,float64:!1,flushToZero:!1,forceEndian:null,ignoreOriginalEncoding:!1,largeNegativeAsBigInt:!1,reduceUnsafeNumbers:!1,rejectBigInts:!1,rejectCustomSimples:!1,rejectDuplicateKeys:!1,rejectFloats:!1,rejectUndefined:!1,simplifyNegativeZero:!1,sortKeys:null,stringNormalization:null,types:null,wtf8:!1,ignoreGlobalTags:!1},mu={cde:!0,ignoreOriginalEncoding:!0,sortKeys:cl},Mp={...mu,dcbor:!0,largeNegativeAsBigInt:!0,reduceUnsafeNumbers:!0,rejectCustomSimples:!0,rejectDuplicateKeys:!0,rejectUndefined:!0,simplifyNegativeZero:!0,stringNormalization:"NFC"};function wp(n){let e=n<0;return typeof n=="bigint"?[e?-n-1n:n,e]:[e?-n-1:n,e]}function pu(n,e,t){if(t.rejectFloats)throw new Error(`Attempt to encode an unwanted floating point number: ${n}`);if(isNaN(n))e.writeUint8(Sp),e.writeUint16(32256);else if(!t.float64&&Math.fround(n)===n){let i=fl(n);i===null?(e.writeUint8(K_),e.writeFloat32(n)):(e.writeUint8(Sp),e.writeUint16(i))}else e.writeUint8(J_),e.writeFloat64(n)}function jn(n,e,t){let[i,s]=wp(n);if(s&&t)throw new TypeError(`Negative size: ${n}`);t??=s?ve.NEG_INT:ve.POS_INT,t<<=5,i<24?e.writeUint8(t|i):i<=255?(e.writeUint8(t|ht.ONE),e.writeUint8(i)):i<=65535?(e.writeUint8(t|ht.TWO),e.writeUint16(i)):i<=4294967295?(e.writeUint8(t|ht.FOUR),e.writeUint32(i)):(e.writeUint8(t|ht.EIGHT),e.writeBigUint64(BigInt(i)))}function mr(n,e,t){typeof n=="number"?jn(n,e,ve.TAG):typeof n=="object"&&!t.ignoreOriginalEncoding&&Jt.ENCODED in n?e.write(n[Jt.ENCODED]):n<=Number.MAX_SAFE_INTEGER?jn(Number(n),e,ve.TAG):(e.writeUint8(ve.TAG<<5|ht.EIGHT),e.writeBigUint64(BigInt(n)))}function Ep(n,e,t){let[i,s]=wp(n);if(t.collapseBigInts&&(!t.largeNegativeAsBigInt||n>=-0x8000000000000000n)){if(i<=0xffffffffn){jn(Number(n),e);return}if(i<=0xffffffffffffffffn){let c=(s?ve.NEG_INT:ve.POS_INT)<<5;e.writeUint8(c|ht.EIGHT),e.writeBigUint64(i);return}}if(t.rejectBigInts)throw new Error(`Attempt to encode unwanted bigint: ${n}`);let r=s?Mt.NEG_BIGINT:Mt.POS_BIGINT,o=i.toString(16),a=o.length%2?"0":"";mr(r,e,t);let l=ll(a+o);jn(l.length,e,ve.BYTE_STRING),e.write(l)}function sy(n,e,t){t.flushToZero&&(n=yp(n)),Object.is(n,-0)?t.simplifyNegativeZero?t.avoidInts?pu(0,e,t):jn(0,e):pu(n,e,t):!t.avoidInts&&Number.isSafeInteger(n)?jn(n,e):t.reduceUnsafeNumbers&&Math.floor(n)===n&&n>=Yr.MIN&&n<=Yr.MAX?Ep(BigInt(n),e,t):pu(n,e,t)}function Tp(n,e,t){let i=t.stringNormalization?n.normalize(t.stringNormalization):n;if(t.wtf8&&!n.isWellFormed()){let s=iy.encode(i);mr(Mt.WTF8,e,t),jn(s.length,e,ve.BYTE_STRING),e.write(s)}else{let s=ny.encode(i);jn(s.length,e,ve.UTF8_STRING),e.write(s)}}function ry(n,e,t){let i=n;yl(i,i.length,ve.ARRAY,e,t);for(let s of i)ks(s,e,t)}function oy(n,e){jn(n.length,e,ve.BYTE_STRING),e.write(n)}var gl=new Qo;gl.registerEncoder(Array,ry),gl.registerEncoder(Uint8Array,oy);function sn(n,e){return gl.registerEncoder(n,e)}function yl(n,e,t,i,s){let r=np(n);r&&!s.ignoreOriginalEncoding?i.write(r):jn(e,i,t)}function ay(n,e,t){if(n===null){e.writeUint8(ty);return}if(!t.ignoreOriginalEncoding&&Jt.ENCODED in n){e.write(n[Jt.ENCODED]);return}let i=n.constructor;if(i){let r=t.types?.get(i)??(t.ignoreGlobalTags?void 0:gl.get(i));if(r){let o=r(n,e,t);if(o!==void 0){if(!Array.isArray(o)||o.length!==2)throw new Error("Invalid encoder return value");(typeof o[0]=="bigint"||isFinite(Number(o[0])))&&mr(o[0],e,t),ks(o[1],e,t)}return}}if(typeof n.toCBOR=="function"){let r=n.toCBOR(e,t);r&&((typeof r[0]=="bigint"||isFinite(Number(r[0])))&&mr(r[0],e,t),ks(r[1],e,t));return}if(typeof n.toJSON=="function"){ks(n.toJSON(),e,t);return}let s=Object.entries(n).map(r=>[r[0],r[1],zs(r[0],t)]);t.sortKeys&&s.sort(t.sortKeys),yl(n,s.length,ve.MAP,e,t);for(let[r,o,a]of s)e.write(a),ks(o,e,t)}function ly(n,e,t){if(!n.description||n!==Symbol.for(n.description))throw new TypeError(`Private or empty symbol: ${n.toString()}`);mr(280,e,t),Tp(n.description,e,t)}function ks(n,e,t){switch(typeof n){case"number":sy(n,e,t);break;case"bigint":Ep(n,e,t);break;case"string":Tp(n,e,t);break;case"boolean":e.writeUint8(n?j_:Q_);break;case"undefined":if(t.rejectUndefined)throw new Error("Attempt to encode unwanted undefined.");e.writeUint8(ey);break;case"object":ay(n,e,t);break;case"symbol":ly(n,e,t);break;default:throw new TypeError(`Unknown type: ${typeof n}, ${String(n)}`)}}function zs(n,e={}){let t={..._l};e.dcbor?Object.assign(t,Mp):e.cde&&Object.assign(t,mu),Object.assign(t,e);let i=new Zr(t);return ks(n,i,t),i.read()}var gr=(n=>(n[n.NEVER=-1]="NEVER",n[n.PREFERRED=0]="PREFERRED",n[n.ALWAYS=1]="ALWAYS",n))(gr||{});var Ii=class n{static KnownSimple=new Map([[Ki.FALSE,!1],[Ki.TRUE,!0],[Ki.NULL,null],[Ki.UNDEFINED,void 0]]);value;constructor(e){this.value=e}static create(e){return n.KnownSimple.has(e)?n.KnownSimple.get(e):new n(e)}toCBOR(e,t){if(t.rejectCustomSimples)throw new Error(`Cannot encode non-standard Simple value: ${this.value}`);jn(this.value,e,ve.SIMPLE_FLOAT)}toString(){return`simple(${this.value})`}decode(){return n.KnownSimple.has(this.value)?n.KnownSimple.get(this.value):this}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return`simple(${i(this.value,t)})`}};var cy=new TextDecoder("utf8",{fatal:!0,ignoreBOM:!0}),Ji=class n{static defaultOptions={maxDepth:1024,encoding:"hex",requirePreferred:!1};#e;#t;#n=0;#i;constructor(e,t){if(this.#i={...n.defaultOptions,...t},typeof e=="string")switch(this.#i.encoding){case"hex":this.#e=ll(e);break;case"base64":this.#e=jo(e);break;default:throw new TypeError(`Encoding not implemented: "${this.#i.encoding}"`)}else this.#e=e;this.#t=new DataView(this.#e.buffer,this.#e.byteOffset,this.#e.byteLength)}toHere(e){return Jo(this.#e,e,this.#n)}*[Symbol.iterator](){if(yield*this.#s(0),this.#n!==this.#e.length)throw new Error("Extra data in input")}*seq(){for(;this.#n<this.#e.length;)yield*this.#s(0)}*#s(e){if(e++>this.#i.maxDepth)throw new Error(`Maximum depth ${this.#i.maxDepth} exceeded`);let t=this.#n,i=this.#t.getUint8(this.#n++),s=i>>5,r=i&31,o=r,a=!1,l=0;switch(r){case ht.ONE:if(l=1,o=this.#t.getUint8(this.#n),s===ve.SIMPLE_FLOAT){if(o<32)throw new Error(`Invalid simple encoding in extra byte: ${o}`);a=!0}else if(this.#i.requirePreferred&&o<24)throw new Error(`Unexpectedly long integer encoding (1) for ${o}`);break;case ht.TWO:if(l=2,s===ve.SIMPLE_FLOAT)o=fu(this.#e,this.#n);else if(o=this.#t.getUint16(this.#n,!1),this.#i.requirePreferred&&o<=255)throw new Error(`Unexpectedly long integer encoding (2) for ${o}`);break;case ht.FOUR:if(l=4,s===ve.SIMPLE_FLOAT)o=this.#t.getFloat32(this.#n,!1);else if(o=this.#t.getUint32(this.#n,!1),this.#i.requirePreferred&&o<=65535)throw new Error(`Unexpectedly long integer encoding (4) for ${o}`);break;case ht.EIGHT:{if(l=8,s===ve.SIMPLE_FLOAT)o=this.#t.getFloat64(this.#n,!1);else if(o=this.#t.getBigUint64(this.#n,!1),o<=Number.MAX_SAFE_INTEGER&&(o=Number(o)),this.#i.requirePreferred&&o<=4294967295)throw new Error(`Unexpectedly long integer encoding (8) for ${o}`);break}case 28:case 29:case 30:throw new Error(`Additional info not implemented: ${r}`);case ht.INDEFINITE:switch(s){case ve.POS_INT:case ve.NEG_INT:case ve.TAG:throw new Error(`Invalid indefinite encoding for MT ${s}`);case ve.SIMPLE_FLOAT:yield[s,r,Jt.BREAK,t,0];return}o=1/0;break;default:a=!0}switch(this.#n+=l,s){case ve.POS_INT:yield[s,r,o,t,l];break;case ve.NEG_INT:yield[s,r,typeof o=="bigint"?-1n-o:-1-Number(o),t,l];break;case ve.BYTE_STRING:o===1/0?yield*this.#l(s,e,t):yield[s,r,this.#r(o),t,o];break;case ve.UTF8_STRING:o===1/0?yield*this.#l(s,e,t):yield[s,r,cy.decode(this.#r(o)),t,o];break;case ve.ARRAY:if(o===1/0)yield*this.#l(s,e,t,!1);else{let c=Number(o);yield[s,r,c,t,l];for(let h=0;h<c;h++)yield*this.#s(e+1)}break;case ve.MAP:if(o===1/0)yield*this.#l(s,e,t,!1);else{let c=Number(o);yield[s,r,c,t,l];for(let h=0;h<c;h++)yield*this.#s(e),yield*this.#s(e)}break;case ve.TAG:yield[s,r,o,t,l],yield*this.#s(e);break;case ve.SIMPLE_FLOAT:{let c=o;a&&(o=Ii.create(Number(o))),yield[s,r,o,t,c];break}}}#r(e){let t=Jo(this.#e,this.#n,this.#n+=e);if(t.length!==e)throw new Error(`Unexpected end of stream reading ${e} bytes, got ${t.length}`);return t}*#l(e,t,i,s=!0){for(yield[e,ht.INDEFINITE,1/0,i,1/0];;){let r=this.#s(t),o=r.next(),[a,l,c]=o.value;if(c===Jt.BREAK){yield o.value,r.next();return}if(s){if(a!==e)throw new Error(`Unmatched major type.  Expected ${e}, got ${a}.`);if(l===ht.INDEFINITE)throw new Error("New stream started in typed stream")}yield o.value,yield*r}}};var hy=new Map([[ht.ZERO,1],[ht.ONE,2],[ht.TWO,3],[ht.FOUR,5],[ht.EIGHT,9]]),uy=new Uint8Array(0);function fy(n,e){return!e.boxed&&!e.preferMap&&n.every(([t])=>typeof t=="string")?Object.fromEntries(n):new Map(n)}var _n=class n{static defaultDecodeOptions={...Ji.defaultOptions,ParentType:n,boxed:!1,cde:!1,dcbor:!1,diagnosticSizes:gr.PREFERRED,collapseBigInts:!1,convertUnsafeIntsToFloat:!1,createObject:fy,keepNanPayloads:!1,pretty:!1,preferBigInt:!1,preferMap:!1,rejectLargeNegatives:!1,rejectBigInts:!1,rejectDuplicateKeys:!1,rejectFloats:!1,rejectInts:!1,rejectLongLoundNaN:!1,rejectLongFloats:!1,rejectNegativeZero:!1,rejectSimple:!1,rejectStreaming:!1,rejectStringsNotNormalizedAs:null,rejectSubnormals:!1,rejectUndefined:!1,rejectUnsafeFloatInts:!1,saveOriginal:!1,sortKeys:null,tags:null,ignoreGlobalTags:!1};static cdeDecodeOptions={cde:!0,rejectStreaming:!0,requirePreferred:!0,sortKeys:cl};static dcborDecodeOptions={...this.cdeDecodeOptions,dcbor:!0,convertUnsafeIntsToFloat:!0,rejectDuplicateKeys:!0,rejectLargeNegatives:!0,rejectLongLoundNaN:!0,rejectLongFloats:!0,rejectNegativeZero:!0,rejectSimple:!0,rejectUndefined:!0,rejectUnsafeFloatInts:!0,rejectStringsNotNormalizedAs:"NFC"};parent;mt;ai;left;offset;count=0;children=[];depth=0;#e;#t=null;constructor(e,t,i,s){if([this.mt,this.ai,,this.offset]=e,this.left=t,this.parent=i,this.#e=s,i&&(this.depth=i.depth+1),this.mt===ve.MAP&&(this.#e.sortKeys||this.#e.rejectDuplicateKeys)&&(this.#t=[]),this.#e.rejectStreaming&&this.ai===ht.INDEFINITE)throw new Error("Streaming not supported")}get isStreaming(){return this.left===1/0}get done(){return this.left===0}static create(e,t,i,s){let[r,o,a,l]=e;switch(r){case ve.POS_INT:case ve.NEG_INT:{if(i.rejectInts)throw new Error(`Unexpected integer: ${a}`);if(i.rejectLargeNegatives&&a<-0x8000000000000000n)throw new Error(`Invalid 65bit negative number: ${a}`);let c=a;return i.preferBigInt?c=BigInt(c):i.convertUnsafeIntsToFloat&&c>=Yr.MIN&&c<=Yr.MAX&&(c=Number(a)),i.boxed?Bs(c,s.toHere(l)):c}case ve.SIMPLE_FLOAT:if(o>ht.ONE){if(typeof a=="symbol")return a;if(i.rejectFloats)throw new Error(`Decoding unwanted floating point number: ${a}`);if(i.rejectNegativeZero&&Object.is(a,-0))throw new Error("Decoding negative zero");if(isNaN(a)){let c=s.toHere(l),h=new ia(c);if(i.rejectLongLoundNaN){if(h.payload||c.length>3)throw new Error(`Invalid NaN encoding: "${On(c)}"`)}else if(i.keepNanPayloads&&(h.payload||h.sign===-1)){if(i.rejectLongFloats&&!h.isShortestEncoding)throw new Error(`NaN should have been encoded shorter: ${a}`);return h}}if(i.rejectSubnormals&&xp(s.toHere(l+1)),i.rejectLongFloats){let c=zs(a,{chunkSize:9,reduceUnsafeNumbers:i.rejectUnsafeFloatInts});if(c[0]>>5!==r)throw new Error(`Should have been encoded as int, not float: ${a}`);if(c.length<hy.get(o))throw new Error(`Number should have been encoded shorter: ${a}`)}if(typeof a=="number"&&i.boxed)return Bs(a,s.toHere(l))}else{if(i.rejectSimple&&a instanceof Ii)throw new Error(`Invalid simple value: ${a}`);if(i.rejectUndefined&&a===void 0)throw new Error("Unexpected undefined")}return a;case ve.BYTE_STRING:case ve.UTF8_STRING:if(a===1/0)return new i.ParentType(e,1/0,t,i);if(i.rejectStringsNotNormalizedAs&&typeof a=="string"){let c=a.normalize(i.rejectStringsNotNormalizedAs);if(a!==c)throw new Error(`String not normalized as "${i.rejectStringsNotNormalizedAs}", got [${cu(a)}] instead of [${cu(c)}]`)}return i.boxed?Bs(a,s.toHere(l)):a;case ve.ARRAY:return new i.ParentType(e,a,t,i);case ve.MAP:return new i.ParentType(e,a*2,t,i);case ve.TAG:{let c=new i.ParentType(e,1,t,i);return c.children=new nt(a),c}}throw new TypeError(`Invalid major type: ${r}`)}static decodeToEncodeOpts(e){return{..._l,avoidInts:e.rejectInts,float64:!e.rejectLongFloats,flushToZero:e.rejectSubnormals,largeNegativeAsBigInt:e.rejectLargeNegatives,sortKeys:e.sortKeys}}push(e,t,i){if(this.children.push(e),this.#t){let s=Os(e)||t.toHere(i);this.#t.push(s)}return--this.left}replaceLast(e,t,i){let s,r=-1/0;if(this.children instanceof nt?(r=0,s=this.children.contents,this.children.contents=e):(r=this.children.length-1,s=this.children[r],this.children[r]=e),this.#t){let o=Os(e)||i.toHere(t.offset);this.#t[r]=o}return s}convert(e){let t;switch(this.mt){case ve.ARRAY:t=this.children;break;case ve.MAP:{let i=this.#n();if(this.#e.sortKeys){let s;for(let r of i){if(s&&this.#e.sortKeys(s,r)>=0)throw new Error(`Duplicate or out of order key: "0x${r[2]}"`);s=r}}else if(this.#e.rejectDuplicateKeys){let s=new Set;for(let[r,o,a]of i){let l=On(a);if(s.has(l))throw new Error(`Duplicate key: "0x${l}"`);s.add(l)}}t=this.#e.createObject(i,this.#e);break}case ve.BYTE_STRING:return sp(this.children);case ve.UTF8_STRING:{let i=this.children.join("");t=this.#e.boxed?Bs(i,e.toHere(this.offset)):i;break}case ve.TAG:t=this.children.decode(this.#e);break;default:throw new TypeError(`Invalid mt on convert: ${this.mt}`)}return this.#e.saveOriginal&&t&&typeof t=="object"&&Fs(t,e.toHere(this.offset)),t}#n(){let e=this.children,t=e.length;if(t%2)throw new Error("Missing map value");let i=new Array(t/2);if(this.#t)for(let s=0;s<t;s+=2)i[s>>1]=[e[s],e[s+1],this.#t[s]];else for(let s=0;s<t;s+=2)i[s>>1]=[e[s],e[s+1],uy];return i}};var gu="  ",dy=new TextEncoder,xl=class extends _n{close="";quote='"';get isEmptyStream(){return(this.mt===ve.UTF8_STRING||this.mt===ve.BYTE_STRING)&&this.count===0}};function Gs(n,e,t,i){let s="";if(e===ht.INDEFINITE)s+="_";else{if(i.diagnosticSizes===gr.NEVER)return"";{let r=i.diagnosticSizes===gr.ALWAYS;if(!r){let o=ht.ZERO;if(Object.is(t,-0))o=ht.TWO;else if(n===ve.POS_INT||n===ve.NEG_INT){let a=t<0,l=typeof t=="bigint"?1n:1,c=a?-t-l:t;c<=23?o=Number(c):c<=255?o=ht.ONE:c<=65535?o=ht.TWO:c<=4294967295?o=ht.FOUR:o=ht.EIGHT}else isFinite(t)?Math.fround(t)===t?fl(t)==null?o=ht.FOUR:o=ht.TWO:o=ht.EIGHT:o=ht.TWO;r=o!==e}r&&(s+="_",e<ht.ONE?s+="i":s+=String(e-24))}}return s}function _u(n,e){let t={..._n.defaultDecodeOptions,...e,ParentType:xl},i=new Ji(n,t),s,r,o="";for(let a of i){let[l,c,h]=a;switch(s&&(s.count>0&&h!==Jt.BREAK&&(s.mt===ve.MAP&&s.count%2?o+=": ":(o+=",",t.pretty||(o+=" "))),t.pretty&&(s.mt!==ve.MAP||s.count%2===0)&&(o+=`
${gu.repeat(s.depth+1)}`)),r=_n.create(a,s,t,i),l){case ve.POS_INT:case ve.NEG_INT:o+=String(h),o+=Gs(l,c,h,t);break;case ve.SIMPLE_FLOAT:if(h!==Jt.BREAK)if(typeof h=="number"){let f=Object.is(h,-0)?"-0.0":String(h);o+=f,isFinite(h)&&!/[.e]/.test(f)&&(o+=".0"),o+=Gs(l,c,h,t)}else h instanceof Ii?(o+="simple(",o+=String(h.value),o+=Gs(ve.POS_INT,c,h.value,t),o+=")"):o+=String(h);break;case ve.BYTE_STRING:h===1/0?(o+="(_ ",r.close=")",r.quote="'"):(o+="h'",o+=On(h),o+="'",o+=Gs(ve.POS_INT,c,h.length,t));break;case ve.UTF8_STRING:h===1/0?(o+="(_ ",r.close=")"):(o+=JSON.stringify(h),o+=Gs(ve.POS_INT,c,dy.encode(h).length,t));break;case ve.ARRAY:{o+="[";let f=Gs(ve.POS_INT,c,h,t);o+=f,f&&(o+=" "),t.pretty&&h?r.close=`
${gu.repeat(r.depth)}]`:r.close="]";break}case ve.MAP:{o+="{";let f=Gs(ve.POS_INT,c,h,t);o+=f,f&&(o+=" "),t.pretty&&h?r.close=`
${gu.repeat(r.depth)}}`:r.close="}";break}case ve.TAG:o+=String(h),o+=Gs(ve.POS_INT,c,h,t),o+="(",r.close=")";break}if(r===Jt.BREAK)if(s?.isStreaming)s.left=0;else throw new Error("Unexpected BREAK");else s&&(s.count++,s.left--);for(r instanceof xl&&(s=r);s?.done;){if(s.isEmptyStream)o=o.slice(0,-3),o+=`${s.quote}${s.quote}_`;else{if(s.mt===ve.MAP&&s.count%2!==0)throw new Error(`Odd streaming map size: ${s.count}`);o+=s.close}s=s.parent}}return o}var py=new TextDecoder,oa=class extends _n{depth=0;leaf=!1;value;length;[Jt.ENCODED];constructor(e,t,i,s){super(e,t,i,s),this.parent?this.depth=this.parent.depth+1:this.depth=s.initialDepth,[,,this.value,,this.length]=e}numBytes(){switch(this.ai){case ht.ONE:return 1;case ht.TWO:return 2;case ht.FOUR:return 4;case ht.EIGHT:return 8}return 0}};function Ap(n){return n instanceof oa}function vl(n,e){return n===1/0?"Indefinite":e?`${n} ${e}${n!==1&&n!==1n?"s":""}`:String(n)}function ra(n){return"".padStart(n," ")}function Rp(n,e,t){let i="";i+=ra(n.depth*2);let s=Os(n);i+=On(s.subarray(0,1));let r=n.numBytes();r&&(i+=" ",i+=On(s.subarray(1,r+1))),i=i.padEnd(e.minCol+1," "),i+="-- ",t!==void 0&&(i+=ra(n.depth*2),t!==""&&(i+=`[${t}] `));let o=!1,[a]=n.children;switch(n.mt){case ve.POS_INT:i+=`Unsigned: ${a}`,typeof a=="bigint"&&(i+="n");break;case ve.NEG_INT:i+=`Negative: ${a}`,typeof a=="bigint"&&(i+="n");break;case ve.BYTE_STRING:i+=`Bytes (Length: ${vl(n.length)})`;break;case ve.UTF8_STRING:i+=`UTF8 (Length: ${vl(n.length)})`,n.length!==1/0&&(i+=`: ${JSON.stringify(a)}`);break;case ve.ARRAY:i+=`Array (Length: ${vl(n.value,"item")})`;break;case ve.MAP:i+=`Map (Length: ${vl(n.value,"pair")})`;break;case ve.TAG:{i+=`Tag #${n.value}`;let l=n.children,[c]=l.contents.children,h=new nt(l.tag,c);Fs(h,s);let f=h.comment(e,n.depth);f&&(i+=": ",i+=f),o||=h.noChildren;break}case ve.SIMPLE_FLOAT:a===Jt.BREAK?i+="BREAK":n.ai>ht.ONE?Object.is(a,-0)?i+="Float: -0":i+=`Float: ${a}`:(i+="Simple: ",a instanceof Ii?i+=a.value:i+=a);break}if(!o)if(n.leaf){if(i+=`
`,s.length>r+1){let l=ra((n.depth+1)*2),c=Ko(s);if(c?.length){c.sort((f,u)=>f[0]-u[0]||u[1]-f[1]);let h=0;for(let[f,u,m]of c)if(!(f<h)){if(h=f+u,m==="<<"){i+=ra(e.minCol+1),i+="--",i+=l,i+="<< ";let g=Jo(s,f,f+u),v=Ko(g);if(v){let d=v.findIndex(([p,x,A])=>p===0&&x===u&&A==="<<");d>=0&&v.splice(d,1)}i+=_u(g),i+=` >>
`,i+=bl(g,{initialDepth:n.depth+1,minCol:e.minCol,noPrefixHex:!0});continue}else m==="'"&&(i+=ra(e.minCol+1),i+="--",i+=l,i+="'",i+=py.decode(s.subarray(f,f+u)),i+=`'
`);if(f>r)for(let g=f;g<f+u;g+=8){let v=Math.min(g+8,f+u);i+=l,i+=On(s.subarray(g,v)),i+=`
`}}}else for(let h=r+1;h<s.length;h+=8)i+=l,i+=On(s.subarray(h,h+8)),i+=`
`}}else{i+=`
`;let l=0;for(let c of n.children){if(Ap(c)){let h=String(l);n.mt===ve.MAP?h=l%2?`val ${(l-1)/2}`:`key ${l/2}`:n.mt===ve.TAG&&(h=""),i+=Rp(c,e,h)}l++}}return i}var my={..._n.defaultDecodeOptions,initialDepth:0,noPrefixHex:!1,minCol:0};function bl(n,e){let t={...my,...e,ParentType:oa,saveOriginal:!0},i=new Ji(n,t),s,r;for(let a of i){if(r=_n.create(a,s,t,i),a[2]===Jt.BREAK)if(s?.isStreaming)s.left=1;else throw new Error("Unexpected BREAK");if(!Ap(r)){let h=new oa(a,0,s,t);h.leaf=!0,h.children.push(r),Fs(h,i.toHere(a[3])),r=h}let l=(r.depth+1)*2,c=r.numBytes();for(c&&(l+=1,l+=c*2),t.minCol=Math.max(t.minCol,l),s&&s.push(r,i,a[3]),s=r;s?.done;)r=s,r.leaf||Fs(r,i.toHere(r.offset)),{parent:s}=s}e&&(e.minCol=t.minCol);let o=t.noPrefixHex?"":`0x${On(i.toHere(0))}
`;return o+=Rp(r,t),o}var Cp=!op();function wl(n){if(typeof n=="object"&&n){if(n.constructor!==Number)throw new Error(`Expected number: ${n}`)}else if(typeof n!="number")throw new Error(`Expected number: ${n}`)}function ds(n){if(typeof n=="object"&&n){if(n.constructor!==String)throw new Error(`Expected string: ${n}`)}else if(typeof n!="string")throw new Error(`Expected string: ${n}`)}function ps(n){if(!(n instanceof Uint8Array))throw new Error(`Expected Uint8Array: ${n}`)}function Up(n){if(!Array.isArray(n))throw new Error(`Expected Array: ${n}`)}sn(Map,(n,e,t)=>{let i=[...n.entries()].map(s=>[s[0],s[1],zs(s[0],t)]);if(t.rejectDuplicateKeys){let s=new Set;for(let[r,o,a]of i){let l=On(a);if(s.has(l))throw new Error(`Duplicate map key: 0x${l}`);s.add(l)}}t.sortKeys&&i.sort(t.sortKeys),yl(n,n.size,ve.MAP,e,t);for(let[s,r,o]of i)e.write(o),ks(r,e,t)});function yu(n){return ds(n.contents),new Date(n.contents)}yu.comment=n=>{ds(n.contents);let e=new Date(n.contents);return`(String ${n.tag===Mt.DATE_FULL?"Full ":""}Date) ${e.toISOString()}`},nt.registerDecoder(Mt.DATE_STRING,yu),nt.registerDecoder(Mt.DATE_FULL,yu);function Ip(n){return wl(n.contents),new Date(n.contents*1e3)}Ip.comment=n=>(wl(n.contents),`(Epoch Date) ${new Date(n.contents*1e3).toISOString()}`),nt.registerDecoder(Mt.DATE_EPOCH,Ip);var bu=1e3*60*60*24;function Pp(n){return wl(n.contents),new Date(n.contents*bu)}Pp.comment=n=>(wl(n.contents),`(Epoch Date) ${new Date(n.contents*bu).toISOString()}`),nt.registerDecoder(Mt.DATE_EPOCH_DAYS,Pp),sn(Date,(n,e,t)=>{switch(t.dateTag){case Mt.DATE_EPOCH:return[t.dateTag,n.valueOf()/1e3];case Mt.DATE_STRING:return[t.dateTag,n.toISOString().replace(/\.000Z$/,"Z")];case Mt.DATE_EPOCH_DAYS:return[t.dateTag,Math.floor(n.valueOf()/bu)];case Mt.DATE_FULL:return[t.dateTag,n.toISOString().split("T")[0]];default:throw new Error(`Unsupported date tag: ${t.dateTag}`)}});function Ml(n,e,t){if(ps(e.contents),t.rejectBigInts)throw new Error(`Decoding unwanted big integer: ${e}(h'${On(e.contents)}')`);if(t.requirePreferred&&e.contents[0]===0)throw new Error(`Decoding overly-large bigint: ${e.tag}(h'${On(e.contents)})`);let i=e.contents.reduce((r,o)=>r<<8n|BigInt(o),0n);n&&(i=-1n-i);let s=i>=Number.MIN_SAFE_INTEGER&&i<=Number.MAX_SAFE_INTEGER;if(t.requirePreferred&&s)throw new Error(`Decoding bigint that could have been int: ${i}n`);return t.collapseBigInts&&s&&(i=Number(i)),t.boxed?Bs(i,e.contents):i}var Lp=Ml.bind(null,!1),Np=Ml.bind(null,!0);Lp.comment=(n,e)=>`(Positive BigInt) ${Ml(!1,n,e)}n`,Np.comment=(n,e)=>`(Negative BigInt) ${Ml(!0,n,e)}n`,nt.registerDecoder(Mt.POS_BIGINT,Lp),nt.registerDecoder(Mt.NEG_BIGINT,Np);function xu(n,e){return ps(n.contents),n}xu.comment=(n,e,t)=>{ps(n.contents);let i={...e,initialDepth:t+2,noPrefixHex:!0},s=Os(n),r=2**((s[0]&31)-24)+1,o=s[r]&31,a=On(s.subarray(r,++r));o>=24&&(a+=" ",a+=On(s.subarray(r,r+2**(o-24)))),i.minCol=Math.max(i.minCol,(t+1)*2+a.length);let l=bl(n.contents,i),c=`Embedded CBOR
`;return c+=`${"".padStart((t+1)*2," ")}${a}`.padEnd(i.minCol+1," "),c+=`-- Bytes (Length: ${n.contents.length})
`,c+=l,c},xu.noChildren=!0,nt.registerDecoder(Mt.CBOR,xu),nt.registerDecoder(Mt.URI,n=>(ds(n.contents),new URL(n.contents)),"URI"),sn(URL,n=>[Mt.URI,n.toString()]),nt.registerDecoder(Mt.BASE64URL,n=>(ds(n.contents),rp(n.contents)),"Base64url-encoded"),nt.registerDecoder(Mt.BASE64,n=>(ds(n.contents),jo(n.contents)),"Base64-encoded"),nt.registerDecoder(35,n=>(ds(n.contents),new RegExp(n.contents)),"RegExp"),nt.registerDecoder(21065,n=>{ds(n.contents);let e=`^(?:${n.contents})$`;return new RegExp(e,"u")},"I-RegExp"),nt.registerDecoder(Mt.REGEXP,n=>{if(Up(n.contents),n.contents.length<1||n.contents.length>2)throw new Error(`Invalid RegExp Array: ${n.contents}`);return new RegExp(n.contents[0],n.contents[1])},"RegExp"),sn(RegExp,n=>[Mt.REGEXP,[n.source,n.flags]]),nt.registerDecoder(64,n=>(ps(n.contents),n.contents),"uint8 Typed Array");function Bn(n,e,t){ps(n.contents);let i=n.contents.length;if(i%e.BYTES_PER_ELEMENT!==0)throw new Error(`Number of bytes must be divisible by ${e.BYTES_PER_ELEMENT}, got: ${i}`);i/=e.BYTES_PER_ELEMENT;let s=new e(i),r=new DataView(n.contents.buffer,n.contents.byteOffset,n.contents.byteLength),o=r[`get${e.name.replace(/Array/,"")}`].bind(r);for(let a=0;a<i;a++)s[a]=o(a*e.BYTES_PER_ELEMENT,t);return s}function Hs(n,e,t,i,s){let r=s.forceEndian??Cp;if(mr(r?e:t,n,s),jn(i.byteLength,n,ve.BYTE_STRING),Cp===r)n.write(new Uint8Array(i.buffer,i.byteOffset,i.byteLength));else{let o=`write${i.constructor.name.replace(/Array/,"")}`,a=n[o].bind(n);for(let l of i)a(l,r)}}nt.registerDecoder(65,n=>Bn(n,Uint16Array,!1),"uint16, big endian, Typed Array"),nt.registerDecoder(66,n=>Bn(n,Uint32Array,!1),"uint32, big endian, Typed Array"),nt.registerDecoder(67,n=>Bn(n,BigUint64Array,!1),"uint64, big endian, Typed Array"),nt.registerDecoder(68,n=>(ps(n.contents),new Uint8ClampedArray(n.contents)),"uint8 Typed Array, clamped arithmetic"),sn(Uint8ClampedArray,n=>[68,new Uint8Array(n.buffer,n.byteOffset,n.byteLength)]),nt.registerDecoder(69,n=>Bn(n,Uint16Array,!0),"uint16, little endian, Typed Array"),sn(Uint16Array,(n,e,t)=>Hs(e,69,65,n,t)),nt.registerDecoder(70,n=>Bn(n,Uint32Array,!0),"uint32, little endian, Typed Array"),sn(Uint32Array,(n,e,t)=>Hs(e,70,66,n,t)),nt.registerDecoder(71,n=>Bn(n,BigUint64Array,!0),"uint64, little endian, Typed Array"),sn(BigUint64Array,(n,e,t)=>Hs(e,71,67,n,t)),nt.registerDecoder(72,n=>(ps(n.contents),new Int8Array(n.contents)),"sint8 Typed Array"),sn(Int8Array,n=>[72,new Uint8Array(n.buffer,n.byteOffset,n.byteLength)]),nt.registerDecoder(73,n=>Bn(n,Int16Array,!1),"sint16, big endian, Typed Array"),nt.registerDecoder(74,n=>Bn(n,Int32Array,!1),"sint32, big endian, Typed Array"),nt.registerDecoder(75,n=>Bn(n,BigInt64Array,!1),"sint64, big endian, Typed Array"),nt.registerDecoder(77,n=>Bn(n,Int16Array,!0),"sint16, little endian, Typed Array"),sn(Int16Array,(n,e,t)=>Hs(e,77,73,n,t)),nt.registerDecoder(78,n=>Bn(n,Int32Array,!0),"sint32, little endian, Typed Array"),sn(Int32Array,(n,e,t)=>Hs(e,78,74,n,t)),nt.registerDecoder(79,n=>Bn(n,BigInt64Array,!0),"sint64, little endian, Typed Array"),sn(BigInt64Array,(n,e,t)=>Hs(e,79,75,n,t)),nt.registerDecoder(81,n=>Bn(n,Float32Array,!1),"IEEE 754 binary32, big endian, Typed Array"),nt.registerDecoder(82,n=>Bn(n,Float64Array,!1),"IEEE 754 binary64, big endian, Typed Array"),nt.registerDecoder(85,n=>Bn(n,Float32Array,!0),"IEEE 754 binary32, little endian, Typed Array"),sn(Float32Array,(n,e,t)=>Hs(e,85,81,n,t)),nt.registerDecoder(86,n=>Bn(n,Float64Array,!0),"IEEE 754 binary64, big endian, Typed Array"),sn(Float64Array,(n,e,t)=>Hs(e,86,82,n,t)),nt.registerDecoder(Mt.SET,(n,e)=>{if(Up(n.contents),e.sortKeys){let t=_n.decodeToEncodeOpts(e),i=null;for(let s of n.contents){let r=[s,void 0,zs(s,t)];if(i&&e.sortKeys(i,r)>=0)throw new Error(`Set items out of order in tag #${Mt.SET}`);i=r}}return new Set(n.contents)},"Set"),sn(Set,(n,e,t)=>{let i=[...n];if(t.sortKeys){let s=i.map(r=>[r,void 0,zs(r,t)]);s.sort(t.sortKeys),i=s.map(([r])=>r)}return[Mt.SET,i]}),nt.registerDecoder(Mt.JSON,n=>(ds(n.contents),JSON.parse(n.contents)),"JSON-encoded");function Dp(n){return ps(n.contents),new pr().decode(n.contents)}Dp.comment=n=>{ps(n.contents);let e=new pr;return`(WTF8 string): ${JSON.stringify(e.decode(n.contents))}`},nt.registerDecoder(Mt.WTF8,Dp),nt.registerDecoder(Mt.SELF_DESCRIBED,n=>n.contents,"Self-Described"),nt.registerDecoder(Mt.INVALID_16,()=>{throw new Error(`Tag always invalid: ${Mt.INVALID_16}`)},"Invalid"),nt.registerDecoder(Mt.INVALID_32,()=>{throw new Error(`Tag always invalid: ${Mt.INVALID_32}`)},"Invalid"),nt.registerDecoder(Mt.INVALID_64,()=>{throw new Error(`Tag always invalid: ${Mt.INVALID_64}`)},"Invalid"),nt.registerDecoder(Mt.SYMBOL,n=>{let e=n.contents;if(Array.isArray(n.contents)){if(n.contents.length!==1)throw new Error(`Expected Array of size 1: ${n.contents}`);[e]=n.contents}if(ds(e),!e.length)throw new Error(`Expected non-empty string: ${n.contents}`);return Symbol.for(e)},"Symbol");function vu(n){throw new Error(`Encoding ${n.constructor.name} intentionally unimplmented.  It is not concrete enough to interoperate.  Convert to Uint8Array first.`)}sn(ArrayBuffer,vu),sn(DataView,vu),typeof SharedArrayBuffer<"u"&&sn(SharedArrayBuffer,vu);function Sl(n){return[NaN,n.valueOf()]}sn(Boolean,Sl),sn(Number,Sl),sn(String,Sl),sn(BigInt,Sl);function gy(n){let e={..._n.defaultDecodeOptions};if(n.dcbor?Object.assign(e,_n.dcborDecodeOptions):n.cde&&Object.assign(e,_n.cdeDecodeOptions),Object.assign(e,n),Object.hasOwn(e,"rejectLongNumbers"))throw new TypeError("rejectLongNumbers has changed to requirePreferred");return e.boxed&&(e.saveOriginal=!0),e}var Su=class{parent=void 0;ret=void 0;step(e,t,i){if(this.ret=_n.create(e,this.parent,t,i),e[2]===Jt.BREAK)if(this.parent?.isStreaming)this.parent.left=0;else throw new Error("Unexpected BREAK");else this.parent&&this.parent.push(this.ret,i,e[3]);for(this.ret instanceof _n&&(this.parent=this.ret);this.parent?.done;){this.ret=this.parent.convert(i);let s=this.parent.parent;s?.replaceLast(this.ret,this.parent,i),this.parent=s}}};function Mu(n,e={}){let t=gy(e),i=new Ji(n,t),s=new Su;for(let r of i)s.step(r,t,i);return s.ret}var{cdeDecodeOptions:SA,dcborDecodeOptions:MA,defaultDecodeOptions:wA}=_n;function _y(n){let e=n instanceof Uint8Array?n:new Uint8Array(n);return Mu(e)}var Vs=class extends Error{},El=class{constructor(e){this.url=e;this.connect()}url;ws=null;subs=new Map;pending=new Map;goals=new Map;statusWaiters=new Map;nextId=1;closed=!1;retryMs=500;onState=()=>{};framesIn=0;bytesIn=0;connect(){this.onState("connecting");let e=new WebSocket(this.url);e.binaryType="arraybuffer",this.ws=e,e.onopen=()=>{this.retryMs=500,this.onState("open");for(let t of this.subs.values())this.sendSubscribe(t)},e.onmessage=t=>this.onFrame(t.data),e.onclose=t=>{this.onState("closed",t.reason||`code ${t.code}`);for(let[i,s]of this.pending)clearTimeout(s.timer),s.reject(new Error("connection to the hub lost")),this.pending.delete(i);this.closed||(setTimeout(()=>this.connect(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))}}close(){this.closed=!0,this.onState=()=>{},this.ws?.close()}send(e){this.ws?.readyState===WebSocket.OPEN&&this.ws.send(JSON.stringify(e))}onFrame(e){let t=performance.now();this.framesIn++;let i,s=typeof e=="string"?e.length:e.byteLength;try{typeof e=="string"?(this.bytesIn+=e.length,i=JSON.parse(e)):(this.bytesIn+=e.byteLength,i=_y(e)),It.busyMs.decode+=performance.now()-t}catch(r){console.warn("undecodable frame from the hub",r);return}switch(i.op){case"publish":{let r=String(i.topic);for(let o of this.subs.values())if(o.topic===r||o.opts.regex&&new RegExp(`^(?:${o.topic})$`).test(r))for(let a of o.handlers)try{a(i.msg,r,t,s)}catch(l){console.error(`handler for ${r} failed`,l)}break}case"service_response":{let r=this.pending.get(String(i.id));if(!r)break;this.pending.delete(String(i.id)),clearTimeout(r.timer),i.result===!1?r.reject(new Vs(typeof i.values=="string"?i.values:JSON.stringify(i.values))):r.resolve(i.values);break}case"action_feedback":{this.goals.get(String(i.id))?.onFeedback(i.values);break}case"action_result":{let r=this.goals.get(String(i.id));if(!r)break;this.goals.delete(String(i.id)),r.done.resolve({status:i.status,values:i.values,result:i.result});break}case"status":{let r=i.id===void 0?void 0:String(i.id);if(i.level==="error"&&r){let o=this.pending.get(r);o&&(this.pending.delete(r),clearTimeout(o.timer),o.reject(new Vs(String(i.msg))));let a=this.goals.get(r);a&&(this.goals.delete(r),a.done.reject(new Vs(String(i.msg)))),this.statusWaiters.get(r)?.(String(i.msg))}i.level==="error"&&!r&&console.warn("hub:",i.msg);break}}}sendSubscribe(e){this.send({op:"subscribe",id:`sub:${e.topic}`,topic:e.topic,type:e.opts.type,compression:e.opts.compression??"cbor",queue_length:e.opts.queue_length??1,throttle_rate:e.opts.throttle_rate??0,regex:e.opts.regex||void 0})}subscribe(e,t,i={}){let s=this.subs.get(e);return s||(s={topic:e,opts:i,handlers:new Set},this.subs.set(e,s),this.sendSubscribe(s)),s.handlers.add(t),()=>{let r=this.subs.get(e);r&&(r.handlers.delete(t),r.handlers.size===0&&(this.subs.delete(e),this.send({op:"unsubscribe",id:`sub:${e}`,topic:e})))}}call(e,t={},i=10){let s=`call:${this.nextId++}`;return new Promise((r,o)=>{let a=window.setTimeout(()=>{this.pending.delete(s),o(new Error(`${e}: no answer within ${i+2} s`))},(i+2)*1e3);this.pending.set(s,{resolve:r,reject:o,timer:a}),this.send({op:"call_service",id:s,service:e,args:t,timeout:i})})}advertise(e,t,i=1500){let s=`adv:${e}:${this.nextId++}`;return new Promise(r=>{let o=window.setTimeout(()=>{this.statusWaiters.delete(s),r(null)},i);this.statusWaiters.set(s,a=>{clearTimeout(o),this.statusWaiters.delete(s),r(a)}),this.send({op:"advertise",id:s,topic:e,type:t})})}unadvertise(e){this.send({op:"unadvertise",topic:e})}publish(e,t,i){let s=`pub:${e}:${this.nextId++}`;i&&(this.statusWaiters.set(s,r=>{this.statusWaiters.delete(s),i(r)}),setTimeout(()=>this.statusWaiters.delete(s),5e3)),this.send({op:"publish",id:s,topic:e,msg:t})}sendGoal(e,t,i,s){let r=`goal:${this.nextId++}`,o=new Promise((a,l)=>{this.goals.set(r,{onFeedback:s,done:{resolve:a,reject:l,timer:0}})});return this.send({op:"send_action_goal",id:r,action:e,action_type:t,args:i,feedback:!0}),{id:r,result:o,cancel:()=>this.send({op:"cancel_action_goal",id:r,action:e})}}};function te(n,e="",t){let i=document.createElement(n);return e&&(i.className=e),t!==void 0&&(i.textContent=t),i}function Ht(n,e=1){return n==null||!Number.isFinite(n)?"–":Math.abs(n)>=100?n.toFixed(0):n.toFixed(e)}function ai(n){if(n==null||!Number.isFinite(n)||n<=0)return"–";let e=["B/s","kB/s","MB/s","GB/s"],t=n,i=0;for(;t>=1e3&&i<e.length-1;)t/=1e3,i++;return`${t.toFixed(t>=100?0:1)} ${e[i]}`}function _r(n){if(!n)return"never";let e=Math.max(0,(Date.now()-n)/1e3);return e<2?"just now":e<90?`${e.toFixed(0)} s ago`:e<5400?`${(e/60).toFixed(0)} min ago`:new Date(n).toLocaleString()}function In(n,e="",t){let i=te("button",e,n);return t&&i.addEventListener("click",t),i}function Jr(n,e="",t=0){if(n!==null&&typeof n=="object"){let s=te("details");t<2&&(s.open=!0);let r=Object.entries(n);s.appendChild(te("summary","",`${e}${e?": ":""}${Array.isArray(n)?`[${r.length}]`:`{${r.length}}`}`));for(let[o,a]of r)s.appendChild(Jr(a,o,t+1));return s}let i=te("div","leaf");return i.appendChild(te("span","key",e?`${e}: `:"")),i.appendChild(te("span",`val ${typeof n}`,JSON.stringify(n)??String(n))),i}function Op(n){n.innerHTML="";let e=te("div","admin"),t=te("section","panel wide");t.appendChild(te("h2","","Audit log"));let i=te("form","filters"),s={};for(let[x,A]of[["principal","user:alice"],["action","publish"],["name_regex","/robot1/.*"]]){let S=te("input");S.name=x,S.placeholder=`${x} e.g. ${A}`,s[x]=S,i.appendChild(S)}let r=te("select");r.name="allowed";for(let[x,A]of[["","allowed and denied"],["true","allowed only"],["false","denied only"]])r.appendChild(new Option(A,x));s.allowed=r,i.appendChild(r);let o=In("Filter","primary");o.type="submit",i.appendChild(o);let a=te("table","audit"),l=te("div","pager"),c=In("Next page →"),h=In("⇤ First page"),f=te("span","muted");l.append(h,c,f),t.append(i,a,l);let u=te("section","panel wide");u.appendChild(te("h2","","Access rules"));let m=te("div");u.appendChild(m),e.append(t,u),n.appendChild(e);let g=50,v=[null],d=0;async function p(){let x=new URLSearchParams({limit:String(g)});for(let[S,C]of Object.entries(s))C.value&&x.set(S,C.value);let A=v[d];A!=null&&x.set("cursor",typeof A=="string"?A:JSON.stringify(A));try{let S=await gn(`/api/v1/audit?${x}`);a.innerHTML="<thead><tr><th>time</th><th>principal</th><th>client</th><th>action</th><th>name</th><th>size</th><th>allowed</th><th>detail</th></tr></thead>";let C=te("tbody");for(let T of S.records){let _=te("tr",T.allowed?"":"denied"),w=T.at?.secs!=null?T.at.secs*1e3:typeof T.at=="number"?T.at>1e12?T.at:T.at*1e3:NaN;for(let U of[Number.isFinite(w)?new Date(w).toLocaleString():JSON.stringify(T.at),T.principal,T.client_ip,T.action,T.name,T.size??"",T.allowed?"yes":"no",T.detail??""])_.appendChild(te("td","",String(U)));C.appendChild(_)}a.appendChild(C),v=v.slice(0,d+1),S.next!=null&&v.push(S.next),c.disabled=S.next==null,h.disabled=d===0,f.textContent=`page ${d+1} · ${S.records.length} records`}catch(S){a.replaceChildren(te("caption","why",`The hub refused the audit log: ${S.message}`)),c.disabled=h.disabled=!0}}return i.addEventListener("submit",x=>{x.preventDefault(),v=[null],d=0,p()}),c.addEventListener("click",()=>{d++,p()}),h.addEventListener("click",()=>{d=0,p()}),p(),gn("/api/v1/rules").then(x=>{let A=te("table","rules");A.innerHTML="<thead><tr><th>id</th><th>subject</th><th>names</th><th>ops</th><th>effect</th><th>comment</th></tr></thead>";let S=te("tbody");for(let C of x.rules){let T=C.rule??C,_=te("tr"),w=T.subject&&typeof T.subject=="object"?Object.entries(T.subject).map(([U,N])=>`${U}:${N}`).join(" "):T.subject;for(let U of[C.id??"",w,T.names,Array.isArray(T.ops)?T.ops.join(", "):T.ops,T.effect??"allow",T.comment??""])_.appendChild(te("td","",typeof U=="string"||typeof U=="number"?String(U):JSON.stringify(U)));S.appendChild(_)}A.appendChild(S),m.replaceChildren(x.rules.length?A:te("p","muted","No rules: only the built-in defaults apply (admin group, robots' own namespaces, anonymous read where enabled)."))},x=>m.replaceChildren(te("p","why",`The hub refused the rules: ${x.message}`))),()=>{}}function aa(n){let e=["B","kB","MB","GB","TB"],t=n,i=0;for(;t>=1e3&&i<e.length-1;)t/=1e3,i++;return`${t.toFixed(t>=100||i===0?0:1)} ${e[i]}`}function Fp(n){return n.split(/\s+/).filter(Boolean)}function yy(n){let e=n.range,t=e.last_s!=null?`last ${e.last_s} s`:e.from_ns!=null?`from ${new Date(e.from_ns/1e6).toLocaleString()}${e.to_ns!=null?` to ${new Date(e.to_ns/1e6).toLocaleString()}`:""}`:"",i=e.topics.length?e.topics.join(" "):"every topic it keeps";return`black box of ${n.robot}${t?`, ${t}`:""}: ${i}`}function xy(n){let e=te("td","",n.error?`${n.state}: ${n.error}`:n.state),t=n.blackbox;if(n.state!=="fetching"||!t)return e;if(t.size!=null){let i=t.size>0?Math.floor(t.received*100/t.size):100,s=te("progress");s.max=Math.max(t.size,1),s.value=Math.min(t.received,s.max),e.append(s,te("div","",`${i}% · ${aa(t.received)} of ${aa(t.size)}`))}else t.received>0&&e.append(te("div","",`${aa(t.received)} received`));return t.waiting&&e.append(te("div","why",t.waiting)),t.resumed>0&&e.append(te("div","muted",`resumed ${t.resumed}×`)),e}function Bp(n){n.innerHTML="";let e=te("section","panel wide");e.appendChild(te("h2","","Recordings"));let t=te("form","filters");t.id="record-form";let i=te("input");i.name="topics",i.placeholder="topics, e.g. /robot1/.* /robot2/scan",i.size=40;let s=te("input");s.name="duration",s.placeholder="duration in s (empty: until stopped)";let r=In("Start recording","primary");r.type="submit";let o=te("span","muted");o.id="record-status",t.append(i,s,r,o);let a=te("form","filters");a.id="blackbox-form";let l=te("select");l.name="robot",l.title="the robot whose black box to read (an offline one is waited for)";let c=te("input");c.name="last_s",c.type="number",c.step="any",c.value="60",c.style.width="6em";let h=te("label","muted","last ");h.append(c," s");let f=te("input");f.name="topics",f.placeholder="the robot's own topics, e.g. /scan /odom (empty: all)",f.size=40;let u=te("input");u.name="name",u.placeholder="name (optional)";let m=In("Fetch black box","primary");m.type="submit";let g=te("span","muted");g.id="blackbox-status",a.append(l,h,f,u,m,g);let v=te("table","recordings");v.id="recordings",e.append(t,a,v),n.appendChild(e);async function d(){try{let _=await gn("/api/v1/recordings");v.innerHTML="<thead><tr><th>id</th><th>state</th><th>topics</th><th>started</th><th>by</th><th>messages</th><th>size</th><th>dropped</th><th>files</th><th></th></tr></thead>";let w=te("tbody");for(let U of _.recordings){let N=te("tr",U.blackbox?`${U.state} blackbox`:U.state);N.dataset.id=U.id,N.append(te("td","",U.id),xy(U)),N.append(te("td","",U.blackbox?yy(U.blackbox):U.spec.topics.join(" ")));for(let B of[_r(U.started_at_ms),U.started_by,String(U.messages),aa(U.bytes),String(U.dropped)])N.appendChild(te("td","",B));let R=te("td");for(let B of U.files){let L=te("a","",B.name),z=Si.token()?`?token=${encodeURIComponent(Si.token())}`:"";L.href=`/api/v1/recordings/${encodeURIComponent(U.id)}/files/${encodeURIComponent(B.name)}${z}`,L.download=B.name,L.title=`${B.messages} messages, ${aa(B.bytes)}`,R.append(L," ")}N.appendChild(R);let G=te("td");U.state==="recording"||U.state==="fetching"?G.appendChild(In("Stop","",()=>S(`/api/v1/recordings/${encodeURIComponent(U.id)}/stop`,"POST"))):G.appendChild(In("Remove","",()=>confirm(`Delete ${U.id} and its files?`)&&S(`/api/v1/recordings/${encodeURIComponent(U.id)}`,"DELETE"))),N.appendChild(G),w.appendChild(N)}v.appendChild(w),_.recordings.length||v.appendChild(te("caption","muted","No recordings yet."))}catch(_){v.replaceChildren(te("caption","why",`The hub refused the recordings: ${_.message}`))}}let p="";async function x(){let _;try{({robots:_}=await gn("/api/v1/robots"))}catch(R){p="";let G=te("option","",`cannot list robots: ${R.message}`);G.value="",l.replaceChildren(G);return}_.sort((R,G)=>R.name.localeCompare(G.name,void 0,{numeric:!0}));let w=_.map(R=>R.online?R.name:`${R.name} (offline)`);if(w.join(`
`)===p&&_.length)return;p=w.join(`
`);let U=l.value,N=_.map((R,G)=>{let B=te("option","",w[G]);return B.value=R.name,B});if(!N.length){let R=te("option","","no robots known");R.value="",N.push(R)}l.replaceChildren(...N),_.some(R=>R.name===U)&&(l.value=U)}async function A(_,w,U,N,R){try{let G=N===void 0?{method:U}:{method:U,body:JSON.stringify(N)},B=await gn(w,G);_.textContent=R?R(B):""}catch(G){_.textContent=`refused: ${G.message}`}d()}let S=(_,w)=>A(o,_,w);t.addEventListener("submit",_=>{_.preventDefault();let w={topics:Fp(i.value)};s.value.trim()&&(w.duration_s=Number(s.value)),A(o,"/api/v1/recordings","POST",w,U=>`started ${U.id}`)}),a.addEventListener("submit",_=>{_.preventDefault();let w={robot:l.value,topics:Fp(f.value)};c.value.trim()&&(w.last_s=Number(c.value)),u.value.trim()&&(w.name=u.value.trim()),A(g,"/api/v1/recordings/blackbox","POST",w,U=>`fetching ${U.id}`)}),d(),x();let C=setInterval(d,2e3),T=setInterval(x,1e4);return()=>{clearInterval(C),clearInterval(T)}}function wu(n){if(n instanceof Uint8Array)return n;if(ArrayBuffer.isView(n))return new Uint8Array(n.buffer,n.byteOffset,n.byteLength);if(typeof n=="string"){let e=atob(n),t=new Uint8Array(e.length);for(let i=0;i<e.length;i++)t[i]=e.charCodeAt(i);return t}return Array.isArray(n)?Uint8Array.from(n):new Uint8Array(0)}function Rl(n){let e=n?.stamp;if(!e)return null;let t=e.sec??e.secs,i=e.nanosec??e.nsecs??0;return typeof t=="number"?t*1e3+i/1e6:null}function Eu(n){return Math.atan2(2*(n.w*n.z+n.x*n.y),1-2*(n.y*n.y+n.z*n.z))}function Cl(n){let e=n?.pose;return e?.pose&&(e=e.pose),!e?.position||!e?.orientation?null:{x:e.position.x,y:e.position.y,yaw:Eu(e.orientation)}}function zp(n){let e=n.ranges??[],t=new Float32Array(e.length*2),i=0;for(let s=0;s<e.length;s++){let r=e[s];if(!(r>=n.range_min&&r<=n.range_max))continue;let o=n.angle_min+s*n.angle_increment;t[i++]=r*Math.cos(o),t[i++]=r*Math.sin(o)}return t.subarray(0,i)}var Tl={1:[1,(n,e)=>n.getInt8(e)],2:[1,(n,e)=>n.getUint8(e)],3:[2,(n,e,t)=>n.getInt16(e,t)],4:[2,(n,e,t)=>n.getUint16(e,t)],5:[4,(n,e,t)=>n.getInt32(e,t)],6:[4,(n,e,t)=>n.getUint32(e,t)],7:[4,(n,e,t)=>n.getFloat32(e,t)],8:[8,(n,e,t)=>n.getFloat64(e,t)]};function Gp(n,e){let t=wu(n.data),i=(n.width??0)*(n.height??1),s=n.point_step,r=!n.is_bigendian,o=_=>n.fields.find(w=>w.name===_),a=o("x"),l=o("y"),c=o("z"),h=o("intensity");if(!a||!l||!c||!s)throw new Error("PointCloud2 without x, y, z fields");let f=e&&e.positions.length>=i*3?e.positions:new Float32Array(i*3),u=e&&e.intensity.length>=i?e.intensity:new Float32Array(i),m=new DataView(t.buffer,t.byteOffset,t.byteLength),g=r&&a.datatype===7&&l.datatype===7&&c.datatype===7,v=Tl[a.datatype][1],d=Tl[l.datatype][1],p=Tl[c.datatype][1],x=h?Tl[h.datatype]?.[1]:void 0,A=n.height??1,S=n.width??0,C=n.row_step||S*s,T=0;for(let _=0;_<A;_++)for(let w=0;w<S;w++){let U=_*C+w*s;if(U+s>t.byteLength)break;let N=g?m.getFloat32(U+a.offset,!0):v(m,U+a.offset,r),R=g?m.getFloat32(U+l.offset,!0):d(m,U+l.offset,r),G=g?m.getFloat32(U+c.offset,!0):p(m,U+c.offset,r);!Number.isFinite(N)||!Number.isFinite(R)||!Number.isFinite(G)||(f[T*3]=N,f[T*3+1]=R,f[T*3+2]=G,u[T]=x?x(m,U+h.offset,r):NaN,T++)}return{positions:f,intensity:u,count:T}}function Hp(n){return n.length>3&&n[0]===255&&n[1]===216&&n[2]===255?"jpeg":n.length>8&&n[0]===137&&n[1]===80&&n[2]===78&&n[3]===71?"png":"unknown"}function Al(n,e=64){if(n instanceof Uint8Array)return`<${n.length} bytes>`;if(ArrayBuffer.isView(n)){let t=Array.from(n).slice(0,e),i=n.length;return i>e?[...t,`… ${i-e} more (${n.constructor.name})`]:t}if(Array.isArray(n)){let t=n.slice(0,e).map(i=>Al(i,e));return n.length>e?[...t,`… ${n.length-e} more`]:t}if(n&&typeof n=="object"){let t={};for(let[i,s]of Object.entries(n))t[i]=Al(s,e);return t}return n}var kp={bool:!1,string:"",float32:0,float64:0,int8:0,uint8:0,int16:0,uint16:0,int32:0,uint32:0,int64:0,uint64:0,byte:0,char:0,time:{sec:0,nanosec:0},duration:{sec:0,nanosec:0}};function Vp(n,e){let t=e?n.find(s=>s.type===e):n[0],i=(s,r)=>{let o={};return!s||r>16||s.fieldnames.forEach((a,l)=>{let c=s.fieldtypes[l],h=s.fieldarraylen?.[l]??-1,f=c in kp?kp[c]:i(n.find(u=>u.type===c),r+1);o[a]=h===-1?f:h===0?[]:Array.from({length:h},()=>f)}),o};return i(t,0)}var vy=["ARROW","CUBE","SPHERE","CYLINDER","LINE_STRIP","LINE_LIST","CUBE_LIST","SPHERE_LIST","POINTS","TEXT_VIEW_FACING","MESH_RESOURCE","TRIANGLE_LIST"],Wp=0,by=2,Sy=3,Xp=(n,e)=>`${n}\0${e}`;function My(n){return n?(n.sec??n.secs??0)*1e3+(n.nanosec??n.nsecs??0)/1e6:0}var Il=class{markers=new Map;apply(e,t){if(Array.isArray(e?.markers))for(let i of e.markers)this.applyOne(i,t);else e&&typeof e=="object"&&this.applyOne(e,t)}applyOne(e,t){let i=e.ns??"",s=e.id??0,r=e.action??Wp;if(r===Sy)if(!i)this.markers.clear();else for(let[o,a]of this.markers)(a.msg.ns??"")===i&&this.markers.delete(o);else if(r===by)this.markers.delete(Xp(i,s));else if(r===Wp||r===1){let o=My(e.lifetime);this.markers.set(Xp(i,s),{msg:e,expires:o>0?t+o:1/0})}}live(e){let t=[];for(let[i,s]of this.markers)s.expires<=e?this.markers.delete(i):t.push(s);return t}nextExpiry(){let e=1/0;for(let t of this.markers.values())e=Math.min(e,t.expires);return e}};function $p(n,e){let t=n??e??{},i=s=>Math.round(Math.min(1,Math.max(0,s??0))*255);return`rgba(${i(t.r)},${i(t.g)},${i(t.b)},${Math.min(1,Math.max(0,t.a??1))})`}function qp(n){let e=n.pose?.position??{},t=n.pose?.orientation,i=e.x??0,s=e.y??0,r=t?Eu(t):0,o=Math.cos(r),a=Math.sin(r),l=n.scale?.x??0,c=n.scale?.y??0,h=n.scale?.z??0,f=$p(n.color),u=(d,p)=>[i+o*d-a*p,s+a*d+o*p],m=Array.from(n.points??[],d=>u(d.x??0,d.y??0)),g=d=>n.colors&&n.colors.length>d?$p(n.colors[d]):f,v=[];switch(n.type){case 0:{let d,p,x,A,S;m.length>=2?([d,p]=m,x=l,A=c||2*l,S=h||Math.hypot(p[0]-d[0],p[1]-d[1])*.3):(d=u(0,0),p=u(l,0),x=c,A=2*c,S=l*.23);let C=Math.hypot(p[0]-d[0],p[1]-d[1]);if(!(C>0))break;let T=(p[0]-d[0])/C,_=(p[1]-d[1])/C,w=-_,U=T;S=Math.min(S,C);let N=[p[0]-T*S,p[1]-_*S],R=x/2,G=A/2;v.push({kind:"polygon",fill:f,pts:[[d[0]+w*R,d[1]+U*R],[N[0]+w*R,N[1]+U*R],[N[0]+w*G,N[1]+U*G],p,[N[0]-w*G,N[1]-U*G],[N[0]-w*R,N[1]-U*R],[d[0]-w*R,d[1]-U*R]]});break}case 1:v.push({kind:"polygon",fill:f,pts:[u(-l/2,-c/2),u(l/2,-c/2),u(l/2,c/2),u(-l/2,c/2)]});break;case 2:case 3:v.push({kind:"ellipse",x:i,y:s,rx:l/2,ry:c/2,yaw:r,fill:f,outline:n.type===3});break;case 4:case 5:{let d=n.type===4?1:2;for(let p=0;p+1<m.length;p+=d)v.push({kind:"polyline",pts:[m[p],m[p+1]],width:l,stroke:g(p)});n.type===4&&!(n.colors&&n.colors.length)&&m.length>1&&(v.length=0,v.push({kind:"polyline",pts:m,width:l,stroke:f}));break}case 6:case 8:m.forEach(([d,p],x)=>v.push({kind:"square",x:d,y:p,w:l,h:n.type===8?c||l:c,fill:g(x)}));break;case 7:m.forEach(([d,p],x)=>v.push({kind:"ellipse",x:d,y:p,rx:l/2,ry:c/2,yaw:0,fill:g(x),outline:!1}));break;case 9:n.text&&v.push({kind:"text",x:i,y:s,height:h,text:n.text,fill:f});break;case 11:for(let d=0;d+2<m.length;d+=3)v.push({kind:"polygon",pts:[m[d],m[d+1],m[d+2]],fill:g(d)});break;default:break}return v}function Yp(n){let e={},t={};for(let{msg:i}of n){let s=vy[i.type??-1]??`type ${i.type}`;e[s]=(e[s]??0)+1;let r=i.ns??"";t[r]=(t[r]??0)+1}return{byType:e,byNs:t}}var wy=6e4,Zp=["#2f80ed","#eb5757","#27ae60","#f2994a","#9b51e0","#56ccf2","#bb6bd9","#219653"];function Kp(n){return Zp[n%Zp.length]}var jr=class{canvas=document.createElement("canvas");robots=new Map;scan=null;goal=null;markers=[];markerExpiry=1/0;selected=null;onClick=null;half=11;dirty=!0;raf=0;ro;constructor(e){this.canvas.className="map",e.appendChild(this.canvas),this.ro=new ResizeObserver(()=>this.invalidate()),this.ro.observe(this.canvas),this.canvas.addEventListener("click",i=>{if(!this.onClick)return;let[s,r]=this.toWorld(i.offsetX,i.offsetY);this.onClick(s,r,i)});let t=()=>{this.markerExpiry<=performance.now()&&(this.dirty=!0),this.dirty&&this.draw(),this.raf=requestAnimationFrame(t)};this.raf=requestAnimationFrame(t)}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.canvas.remove()}invalidate(){this.dirty=!0}setPose(e,t,i){let s=this.robots.get(e);s||(s={name:e,pose:null,trail:[],online:!0,colour:i},this.robots.set(e,s));let r=performance.now();s.pose=t;let o=s.trail[s.trail.length-1];for((!o||Math.hypot(o.x-t.x,o.y-t.y)>.05||r-o.t>500)&&s.trail.push({x:t.x,y:t.y,t:r});s.trail.length&&r-s.trail[0].t>wy;)s.trail.shift();let a=Math.max(Math.abs(t.x),Math.abs(t.y))+1;a>this.half&&(this.half=Math.ceil(a)),this.invalidate()}geometry(){let e=window.devicePixelRatio||1,t=this.canvas.clientWidth,i=this.canvas.clientHeight,s=Math.min(t,i)/(2*this.half);return{dpr:e,w:t,h:i,scale:s,cx:t/2,cy:i/2}}toWorld(e,t){let i=this.geometry();return[(e-i.cx)/i.scale,-(t-i.cy)/i.scale]}toScreen(e,t){let i=this.geometry();return[i.cx+e*i.scale,i.cy-t*i.scale]}draw(){this.dirty=!1;let e=this.geometry();if(e.w===0||e.h===0)return;(this.canvas.width!==Math.round(e.w*e.dpr)||this.canvas.height!==Math.round(e.h*e.dpr))&&(this.canvas.width=Math.round(e.w*e.dpr),this.canvas.height=Math.round(e.h*e.dpr));let t=this.canvas.getContext("2d");t.setTransform(e.dpr,0,0,e.dpr,0,0),t.fillStyle="#0f1720",t.fillRect(0,0,e.w,e.h);let i=(s,r)=>[e.cx+s*e.scale,e.cy-r*e.scale];for(let s=-this.half;s<=this.half;s++){t.strokeStyle=s===0?"#3b4a5a":s%5===0?"#24313e":"#18222c",t.lineWidth=1;let[r,o]=i(s,-this.half),[a,l]=i(s,this.half);t.beginPath(),t.moveTo(r,o),t.lineTo(a,l),t.stroke();let[c,h]=i(-this.half,s),[f,u]=i(this.half,s);t.beginPath(),t.moveTo(c,h),t.lineTo(f,u),t.stroke()}if(t.fillStyle="#5b6b7b",t.font="11px sans-serif",t.fillText(`1 m grid · ${2*this.half} m across`,8,e.h-8),this.markers.length&&this.drawMarkers(t,e.scale,i),this.scan){t.fillStyle="#f2c94c";for(let s=0;s<this.scan.length;s+=2){let[r,o]=i(this.scan[s],this.scan[s+1]);t.fillRect(r-1,o-1,2,2)}}if(this.goal){let[s,r]=i(this.goal.x,this.goal.y);t.strokeStyle="#6fcf97",t.lineWidth=2,t.beginPath(),t.arc(s,r,9,0,Math.PI*2),t.stroke(),t.beginPath(),t.moveTo(s-13,r),t.lineTo(s+13,r),t.moveTo(s,r-13),t.lineTo(s,r+13),t.stroke()}for(let s of this.robots.values()){let r=s.online?s.colour:"#56606a";if(s.trail.length>1&&(t.strokeStyle=r,t.globalAlpha=.55,t.lineWidth=2,t.beginPath(),s.trail.forEach((c,h)=>{let[f,u]=i(c.x,c.y);h===0?t.moveTo(f,u):t.lineTo(f,u)}),t.stroke(),t.globalAlpha=1),!s.pose)continue;let[o,a]=i(s.pose.x,s.pose.y),l=Math.max(9,e.scale*.45);t.save(),t.translate(o,a),t.rotate(-s.pose.yaw),t.fillStyle=r,t.strokeStyle=s.name===this.selected?"#ffffff":"#0b1016",t.lineWidth=2,t.beginPath(),t.moveTo(l,0),t.lineTo(-l*.7,l*.6),t.lineTo(-l*.4,0),t.lineTo(-l*.7,-l*.6),t.closePath(),t.fill(),t.stroke(),t.restore(),t.fillStyle=s.online?"#e0e6ec":"#7b8690",t.font="12px sans-serif",t.fillText(s.online?s.name:`${s.name} (offline)`,o+l+3,a-l*.5)}}drawMarkers(e,t,i){let s=performance.now(),r=this.markers.flatMap(c=>c.live(s));this.markerExpiry=Math.min(...this.markers.map(c=>c.nextExpiry()));let o=0,a=c=>{e.beginPath(),c.forEach(([h,f],u)=>{let[m,g]=i(h,f);u===0?e.moveTo(m,g):e.lineTo(m,g)})},l=c=>{switch(o++,c.kind){case"polygon":a(c.pts),e.closePath(),e.fillStyle=c.fill,e.fill();break;case"ellipse":{let[h,f]=i(c.x,c.y);e.beginPath(),e.ellipse(h,f,Math.max(1,c.rx*t),Math.max(1,c.ry*t),-c.yaw,0,Math.PI*2),e.fillStyle=c.fill,e.fill(),c.outline&&(e.strokeStyle="rgba(11,16,22,0.8)",e.lineWidth=1.5,e.stroke());break}case"polyline":a(c.pts),e.strokeStyle=c.stroke,e.lineWidth=Math.max(1,c.width*t),e.lineJoin="round",e.stroke();break;case"square":{let[h,f]=i(c.x,c.y),u=Math.max(2,c.w*t),m=Math.max(2,c.h*t);e.fillStyle=c.fill,e.fillRect(h-u/2,f-m/2,u,m);break}case"text":{let[h,f]=i(c.x,c.y);e.font=`${Math.max(9,c.height*t)}px sans-serif`,e.textAlign="center",e.textBaseline="middle",e.fillStyle=c.fill,e.fillText(c.text,h,f),e.textAlign="start",e.textBaseline="alphabetic";break}}};for(let c of r)qp(c.msg).forEach(l);It.markers={...Yp(r),drawn:r.length,shapes:o}}};function Tu(n,e){let t=e.filter(r=>r.name.startsWith(`/${n}/`)),i=r=>t.find(o=>o.type===r),s=i("geometry_msgs/msg/PoseStamped")??i("nav_msgs/msg/Odometry")??i("geometry_msgs/msg/PoseWithCovarianceStamped");return s?{topic:s.name,type:s.type}:null}function Ey(n,e){let t=0,i=0,s={};for(let r of e)if(r.name.startsWith(`/${n}/`)){t+=r.rate_hz,i+=r.bandwidth_bps;for(let[o,a]of Object.entries(r.drops??{}))a&&(s[o]=(s[o]??0)+a)}return{rate:t,bw:i,drops:s}}function Jp(n,e,t){n.innerHTML="";let i=te("div","fleet"),s=te("div","panel mapbox");s.appendChild(te("h2","","Fleet map"));let r=te("div","panel side");r.appendChild(te("h2","","Robots"));let o=te("div","robotlist");r.appendChild(o),i.append(s,r),n.appendChild(i);let a=new jr(s);a.onClick=(g,v)=>{let d=null,p=1.2;for(let x of a.robots.values()){if(!x.pose)continue;let A=Math.hypot(x.pose.x-g,x.pose.y-v);A<p&&(d=x.name,p=A)}d&&t(d)};let l=new Map,c=new Map,h=!1;async function f(){let g=[],v=[];try{[{robots:g},{topics:v}]=await Promise.all([gn("/api/v1/robots"),gn("/api/v1/topics")])}catch(d){o.textContent=`cannot list robots: ${d.message}`;return}if(!h){g.sort((d,p)=>d.name.localeCompare(p.name,void 0,{numeric:!0})),g.forEach(d=>{c.has(d.name)||c.set(d.name,Kp(c.size))});for(let d of g){let p=Tu(d.name,v),x=p?.topic;if(d.online&&p&&!l.has(x)){let S=c.get(d.name);l.set(x,e.subscribe(p.topic,C=>{let T=Cl(C);T&&(a.setPose(d.name,T,S),It.poses[d.name]={...T,at:Date.now()},Jn("fleet-pose"))},{type:p.type,throttle_rate:100,queue_length:1,compression:"none"}))}let A=a.robots.get(d.name);A&&A.online!==d.online&&(A.online=d.online,a.invalidate())}u(g,v)}}function u(g,v){o.innerHTML="",g.length===0&&o.appendChild(te("p","muted","No robots visible to you yet."));for(let d of g){let p=Ey(d.name,v),x=te("div",`robot ${d.online?"online":"offline"}`);x.dataset.robot=d.name;let A=te("div","robot-head"),S=te("span","dot");S.style.background=d.online?c.get(d.name):"#56606a",A.append(S,te("b","",d.name),te("span",d.online?"badge ok":"badge off",d.online?"online":`offline · gone ${_r(d.last_seen_ms)}`)),x.appendChild(A);let C=te("dl","kv"),T=(_,w,U="")=>{let N=te("dt","",_),R=te("dd","",w);U&&(R.title=U),C.append(N,R)};if(d.hub?T("hub",d.hub,"connected to this other hub of the federation"):T("last seen",_r(d.last_seen_ms)),d.online&&!d.hub){T("RTT",d.rtt_ms!=null?`${Ht(d.rtt_ms)} ms`:"–"),T("goodput",ai(d.link_rate_bps),"what the robot's link delivered (its link report)"),T("msg/s",Ht(p.rate),`${ai(p.bw)} over ${d.topics.length} topics`);let _=Object.entries(p.drops);T("drops",_.length?_.map(([w,U])=>`${w} ${U}`).join(", "):"none"),T("clock offset",d.clock_offset_ms!=null?`${Ht(d.clock_offset_ms)} ms`:"–"),T("share",d.share_bps?ai(d.share_bps):"unlimited","capacity share of the robot's site")}x.appendChild(C),x.addEventListener("click",()=>t(d.name)),o.appendChild(x)}}f();let m=window.setInterval(f,1e3);return()=>{h=!0,clearInterval(m);for(let g of l.values())g();a.destroy()}}var Ty="uplot",Ay="u-hz",Ry="u-vt",Cy="u-title",Iy="u-wrap",Py="u-under",Ly="u-over",Ny="u-axis",vr="u-off",Dy="u-select",Uy="u-cursor-x",Oy="u-cursor-y",Fy="u-cursor-pt",By="u-legend",ky="u-live",zy="u-inline",Gy="u-series",Hy="u-marker",jp="u-label",Vy="u-value",ca="width",ha="height";var Qp="bottom",Qr="left",Au="right",Wu="#000",em=Wu+"0",Ru="mousemove",tm="mousedown",Cu="mouseup",nm="mouseenter",im="mouseleave",sm="dblclick",Wy="resize",Xy="scroll",rm="change",Ul="dppxchange",Xu="--",oo=typeof window<"u",Du=oo?document:null,to=oo?window:null,$y=oo?navigator:null,Dt,Pl;function Uu(){let n=devicePixelRatio;Dt!=n&&(Dt=n,Pl&&Fu(rm,Pl,Uu),Pl=matchMedia(`(min-resolution: ${Dt-.001}dppx) and (max-resolution: ${Dt+.001}dppx)`),br(rm,Pl,Uu),to.dispatchEvent(new CustomEvent(Ul)))}function li(n,e){if(e!=null){let t=n.classList;!t.contains(e)&&t.add(e)}}function Ou(n,e){let t=n.classList;t.contains(e)&&t.remove(e)}function jt(n,e,t){n.style[e]=t+"px"}function Pi(n,e,t,i){let s=Du.createElement(n);return e!=null&&li(s,e),t?.insertBefore(s,i),s}function Mi(n,e){return Pi("div",n,e)}var om=new WeakMap;function ji(n,e,t,i,s){let r="translate("+e+"px,"+t+"px)",o=om.get(n);r!=o&&(n.style.transform=r,om.set(n,r),e<0||t<0||e>i||t>s?li(n,vr):Ou(n,vr))}var am=new WeakMap;function lm(n,e,t){let i=e+t,s=am.get(n);i!=s&&(am.set(n,i),n.style.background=e,n.style.borderColor=t)}var cm=new WeakMap;function hm(n,e,t,i){let s=e+""+t,r=cm.get(n);s!=r&&(cm.set(n,s),n.style.height=t+"px",n.style.width=e+"px",n.style.marginLeft=i?-e/2+"px":0,n.style.marginTop=i?-t/2+"px":0)}var $u={passive:!0},qy={...$u,capture:!0};function br(n,e,t,i){e.addEventListener(n,t,i?qy:$u)}function Fu(n,e,t,i){e.removeEventListener(n,t,$u)}oo&&Uu();function Li(n,e,t,i){let s;t=t||0,i=i||e.length-1;let r=i<=2147483647;for(;i-t>1;)s=r?t+i>>1:ci((t+i)/2),e[s]<n?t=s:i=s;return n-e[t]<=e[i]-n?t:i}function Bm(n){return(t,i,s)=>{let r=-1,o=-1;for(let a=i;a<=s;a++)if(n(t[a])){r=a;break}for(let a=s;a>=i;a--)if(n(t[a])){o=a;break}return[r,o]}}var km=n=>n!=null,zm=n=>n!=null&&n>0,Bl=Bm(km),Yy=Bm(zm);function Zy(n,e,t,i=0,s=!1){let r=s?Yy:Bl,o=s?zm:km;[e,t]=r(n,e,t);let a=n[e],l=n[e];if(e>-1)if(i==1)a=n[e],l=n[t];else if(i==-1)a=n[t],l=n[e];else for(let c=e;c<=t;c++){let h=n[c];o(h)&&(h<a?a=h:h>l&&(l=h))}return[a??Xt,l??-Xt]}function kl(n,e,t,i){let s=dm(n),r=dm(e);n==e&&(s==-1?(n*=t,e/=t):(n/=t,e*=t));let o=t==10?ms:Gm,a=s==1?ci:wi,l=r==1?wi:ci,c=a(o(Sn(n))),h=l(o(Sn(e))),f=no(t,c),u=no(t,h);return t==10&&(c<0&&(f=$t(f,-c)),h<0&&(u=$t(u,-h))),i||t==2?(n=f*s,e=u*r):(n=Xm(n,f),e=zl(e,u)),[n,e]}function qu(n,e,t,i){let s=kl(n,e,t,i);return n==0&&(s[0]=0),e==0&&(s[1]=0),s}var Yu=.1,um={mode:3,pad:Yu},fa={pad:0,soft:null,mode:0},Ky={min:fa,max:fa};function Ol(n,e,t,i){return Gl(t)?fm(n,e,t):(fa.pad=t,fa.soft=i?0:null,fa.mode=i?3:0,fm(n,e,Ky))}function Lt(n,e){return n??e}function Jy(n,e,t){for(e=Lt(e,0),t=Lt(t,n.length-1);e<=t;){if(n[e]!=null)return!0;e++}return!1}function fm(n,e,t){let i=t.min,s=t.max,r=Lt(i.pad,0),o=Lt(s.pad,0),a=Lt(i.hard,-Xt),l=Lt(s.hard,Xt),c=Lt(i.soft,Xt),h=Lt(s.soft,-Xt),f=Lt(i.mode,0),u=Lt(s.mode,0),m=e-n,g=ms(m),v=qn(Sn(n),Sn(e)),d=ms(v),p=Sn(d-g);(m<1e-24||p>10)&&(m=0,(n==0||e==0)&&(m=1e-24,f==2&&c!=Xt&&(r=0),u==2&&h!=-Xt&&(o=0)));let x=m||v||1e3,A=ms(x),S=no(10,ci(A)),C=x*(m==0?n==0?.1:1:r),T=$t(Xm(n-C,S/10),24),_=n>=c&&(f==1||f==3&&T<=c||f==2&&T>=c)?c:Xt,w=qn(a,T<_&&n>=_?_:Ni(_,T)),U=x*(m==0?e==0?.1:1:o),N=$t(zl(e+U,S/10),24),R=e<=h&&(u==1||u==3&&N>=h||u==2&&N<=h)?h:-Xt,G=Ni(l,N>R&&e<=R?R:qn(R,N));return w==G&&w==0&&(G=100),[w,G]}var jy=new Intl.NumberFormat(oo?$y.language:"en-US"),Zu=n=>jy.format(n),hi=Math,Dl=hi.PI,Sn=hi.abs,ci=hi.floor,bn=hi.round,wi=hi.ceil,Ni=hi.min,qn=hi.max,no=hi.pow,dm=hi.sign,ms=hi.log10,Gm=hi.log2,Qy=(n,e=1)=>hi.sinh(n)*e,Iu=(n,e=1)=>hi.asinh(n/e),Xt=1/0;function pm(n){return(ms((n^n>>31)-(n>>31))|0)+1}function Bu(n,e,t){return Ni(qn(n,e),t)}function Hm(n){return typeof n=="function"}function Tt(n){return Hm(n)?n:()=>n}var ex=()=>{},Vm=n=>n,Wm=(n,e)=>e,tx=n=>null,mm=n=>!0,gm=(n,e)=>n==e,nx=/\.\d*?(?=9{6,}|0{6,})/gm,Sr=n=>{if(qm(n)||Xs.has(n))return n;let e=`${n}`,t=e.match(nx);if(t==null)return n;let i=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${Sr(s)}e${r}`}return $t(n,i)};function yr(n,e){return Sr($t(Sr(n/e))*e)}function zl(n,e){return Sr(wi(Sr(n/e))*e)}function Xm(n,e){return Sr(ci(Sr(n/e))*e)}function $t(n,e=0){if(qm(n))return n;let t=10**e,i=n*t*(1+Number.EPSILON);return bn(i)/t}var Xs=new Map;function $m(n){return((""+n).split(".")[1]||"").length}function pa(n,e,t,i){let s=[],r=i.map($m);for(let o=e;o<t;o++){let a=Sn(o),l=$t(no(n,o),a);for(let c=0;c<i.length;c++){let h=n==10?+`${i[c]}e${o}`:i[c]*l,f=(o>=0?0:a)+(o>=r[c]?0:r[c]),u=n==10?h:$t(h,f);s.push(u),Xs.set(u,f)}}return s}var da={},Ku=[],io=[null,null],Ws=Array.isArray,qm=Number.isInteger,ix=n=>n===void 0;function _m(n){return typeof n=="string"}function Gl(n){let e=!1;if(n!=null){let t=n.constructor;e=t==null||t==Object}return e}function sx(n){return n!=null&&typeof n=="object"}var rx=Object.getPrototypeOf(Uint8Array),Ym="__proto__";function so(n,e=Gl){let t;if(Ws(n)){let i=n.find(s=>s!=null);if(Ws(i)||e(i)){t=Array(n.length);for(let s=0;s<n.length;s++)t[s]=so(n[s],e)}else t=n.slice()}else if(n instanceof rx)t=n.slice();else if(e(n)){t={};for(let i in n)i!=Ym&&(t[i]=so(n[i],e))}else t=n;return t}function yn(n){let e=arguments;for(let t=1;t<e.length;t++){let i=e[t];for(let s in i)s!=Ym&&(Gl(n[s])?yn(n[s],so(i[s])):n[s]=so(i[s]))}return n}var ox=0,ax=1,lx=2;function cx(n,e,t){for(let i=0,s,r=-1;i<e.length;i++){let o=e[i];if(o>r){for(s=o-1;s>=0&&n[s]==null;)n[s--]=null;for(s=o+1;s<t&&n[s]==null;)n[r=s++]=null}}}function hx(n,e){if(dx(n)){let o=n[0].slice();for(let a=1;a<n.length;a++)o.push(...n[a].slice(1));return px(o[0])||(o=fx(o)),o}let t=new Set;for(let o=0;o<n.length;o++){let l=n[o][0],c=l.length;for(let h=0;h<c;h++)t.add(l[h])}let i=[Array.from(t).sort((o,a)=>o-a)],s=i[0].length,r=new Map;for(let o=0;o<s;o++)r.set(i[0][o],o);for(let o=0;o<n.length;o++){let a=n[o],l=a[0];for(let c=1;c<a.length;c++){let h=a[c],f=Array(s).fill(void 0),u=e?e[o][c]:ax,m=[];for(let g=0;g<h.length;g++){let v=h[g],d=r.get(l[g]);v===null?u!=ox&&(f[d]=v,u==lx&&m.push(d)):f[d]=v}cx(f,m,s),i.push(f)}}return i}var ux=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function fx(n){let e=n[0],t=e.length,i=Array(t);for(let r=0;r<i.length;r++)i[r]=r;i.sort((r,o)=>e[r]-e[o]);let s=[];for(let r=0;r<n.length;r++){let o=n[r],a=Array(t);for(let l=0;l<t;l++)a[l]=o[i[l]];s.push(a)}return s}function dx(n){let e=n[0][0],t=e.length;for(let i=1;i<n.length;i++){let s=n[i][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function px(n,e=100){let t=n.length;if(t<=1)return!0;let i=0,s=t-1;for(;i<=s&&n[i]==null;)i++;for(;s>=i&&n[s]==null;)s--;if(s<=i)return!0;let r=qn(1,ci((s-i+1)/e));for(let o=n[i],a=i+r;a<=s;a+=r){let l=n[a];if(l!=null){if(l<=o)return!1;o=l}}return!0}var Zm=["January","February","March","April","May","June","July","August","September","October","November","December"],Km=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Jm(n){return n.slice(0,3)}var mx=Km.map(Jm),gx=Zm.map(Jm),_x={MMMM:Zm,MMM:gx,WWWW:Km,WWW:mx};function la(n){return(n<10?"0":"")+n}function yx(n){return(n<10?"00":n<100?"0":"")+n}var xx={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,e)=>e.MMMM[n.getMonth()],MMM:(n,e)=>e.MMM[n.getMonth()],MM:n=>la(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>la(n.getDate()),D:n=>n.getDate(),WWWW:(n,e)=>e.WWWW[n.getDay()],WWW:(n,e)=>e.WWW[n.getDay()],HH:n=>la(n.getHours()),H:n=>n.getHours(),h:n=>{let e=n.getHours();return e==0?12:e>12?e-12:e},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>la(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>la(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>yx(n.getMilliseconds())};function Ju(n,e){e=e||_x;let t=[],i=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=i.exec(n);)t.push(s[0][0]=="{"?xx[s[1]]:s[0]);return r=>{let o="";for(let a=0;a<t.length;a++)o+=typeof t[a]=="string"?t[a]:t[a](r,e);return o}}var vx=new Intl.DateTimeFormat().resolvedOptions().timeZone;function bx(n,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+n+n.getTimezoneOffset()*6e4):e==vx?t=n:(t=new Date(n.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(n.getMilliseconds())),t}var jm=n=>n%1==0,Fl=[1,2,2.5,5],Sx=pa(10,-32,0,Fl),Qm=pa(10,0,32,Fl),Mx=Qm.filter(jm),xr=Sx.concat(Qm),ju=`
`,eg="{YYYY}",ym=ju+eg,tg="{M}/{D}",ua=ju+tg,Ll=ua+"/{YY}",ng="{aa}",wx="{h}:{mm}",eo=wx+ng,xm=ju+eo,vm=":{ss}",Ot=null;function ig(n){let e=n*1e3,t=e*60,i=t*60,s=i*24,r=s*30,o=s*365,l=(n==1?pa(10,0,3,Fl).filter(jm):pa(10,-3,0,Fl)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,i,i*2,i*3,i*4,i*6,i*8,i*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,o,o*2,o*5,o*10,o*25,o*50,o*100]),c=[[o,eg,Ot,Ot,Ot,Ot,Ot,Ot,1],[s*28,"{MMM}",ym,Ot,Ot,Ot,Ot,Ot,1],[s,tg,ym,Ot,Ot,Ot,Ot,Ot,1],[i,"{h}"+ng,Ll,Ot,ua,Ot,Ot,Ot,1],[t,eo,Ll,Ot,ua,Ot,Ot,Ot,1],[e,vm,Ll+" "+eo,Ot,ua+" "+eo,Ot,xm,Ot,1],[n,vm+".{fff}",Ll+" "+eo,Ot,ua+" "+eo,Ot,xm,Ot,1]];function h(f){return(u,m,g,v,d,p)=>{let x=[],A=d>=o,S=d>=r&&d<o,C=f(g),T=$t(C*n,3),_=Pu(C.getFullYear(),A?0:C.getMonth(),S||A?1:C.getDate()),w=$t(_*n,3);if(S||A){let U=S?d/r:0,N=A?d/o:0,R=T==w?T:$t(Pu(_.getFullYear()+N,_.getMonth()+U,1)*n,3),G=new Date(bn(R/n)),B=G.getFullYear(),L=G.getMonth();for(let z=0;R<=v;z++){let q=Pu(B+N*z,L+U*z,1),O=q-f($t(q*n,3));R=$t((+q+O)*n,3),R<=v&&x.push(R)}}else{let U=d>=s?s:d,N=ci(g)-ci(T),R=w+N+zl(T-w,U);x.push(R);let G=f(R),B=G.getHours()+G.getMinutes()/t+G.getSeconds()/i,L=d/i,z=u.axes[m]._space,q=p/z;for(;R=$t(R+d,n==1?0:3),!(R>v);)if(L>1){let O=ci($t(B+L,6))%24,$=f(R).getHours()-O;$>1&&($=-1),R-=$*i,B=(B+L)%24;let W=x[x.length-1];$t((R-W)/d,3)*q>=.7&&x.push(R)}else x.push(R)}return x}}return[l,c,h]}var[Ex,Tx,Ax]=ig(1),[Rx,Cx,Ix]=ig(.001);pa(2,-53,53,[1]);function bm(n,e){return n.map(t=>t.map((i,s)=>s==0||s==8||i==null?i:e(s==1||t[8]==0?i:t[1]+i)))}function Sm(n,e){return(t,i,s,r,o)=>{let a=e.find(g=>o>=g[0])||e[e.length-1],l,c,h,f,u,m;return i.map(g=>{let v=n(g),d=v.getFullYear(),p=v.getMonth(),x=v.getDate(),A=v.getHours(),S=v.getMinutes(),C=v.getSeconds(),T=d!=l&&a[2]||p!=c&&a[3]||x!=h&&a[4]||A!=f&&a[5]||S!=u&&a[6]||C!=m&&a[7]||a[1];return l=d,c=p,h=x,f=A,u=S,m=C,T(v)})}}function Px(n,e){let t=Ju(e);return(i,s,r,o,a)=>s.map(l=>t(n(l)))}function Pu(n,e,t){return new Date(n,e,t)}function Mm(n,e){return e(n)}var Lx="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function wm(n,e){return(t,i,s,r)=>r==null?Xu:e(n(i))}function Nx(n,e){let t=n.series[e];return t.width?t.stroke(n,e):t.points.width?t.points.stroke(n,e):null}function Dx(n,e){return n.series[e].fill(n,e)}var Ux={show:!0,live:!0,isolate:!1,mount:ex,markers:{show:!0,width:2,stroke:Nx,fill:Dx,dash:"solid"},idx:null,idxs:null,values:[]};function Ox(n,e){let t=n.cursor.points,i=Mi(),s=t.size(n,e);jt(i,ca,s),jt(i,ha,s);let r=s/-2;jt(i,"marginLeft",r),jt(i,"marginTop",r);let o=t.width(n,e,s);return o&&jt(i,"borderWidth",o),i}function Fx(n,e){let t=n.series[e].points;return t._fill||t._stroke}function Bx(n,e){let t=n.series[e].points;return t._stroke||t._fill}function kx(n,e){return n.series[e].points.size}var Lu=[0,0];function zx(n,e,t){return Lu[0]=e,Lu[1]=t,Lu}function Nl(n,e,t,i=!0){return s=>{s.button==0&&(!i||s.target==e)&&t(s)}}function Nu(n,e,t,i=!0){return s=>{(!i||s.target==e)&&t(s)}}var Gx={show:!0,x:!0,y:!0,lock:!1,move:zx,points:{one:!1,show:Ox,size:kx,width:0,stroke:Bx,fill:Fx},bind:{mousedown:Nl,mouseup:Nl,click:Nl,dblclick:Nl,mousemove:Nu,mouseleave:Nu,mouseenter:Nu},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,e,t,i,s)=>i-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},sg={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Qu=yn({},sg,{filter:Wm}),rg=yn({},Qu,{size:10}),og=yn({},sg,{show:!1}),ef='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',ag="bold "+ef,lg=1.5,Em={show:!0,scale:"x",stroke:Wu,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:ag,side:2,grid:Qu,ticks:rg,border:og,font:ef,lineGap:lg,rotate:0},Hx="Value",Vx="Time",Tm={show:!0,scale:"x",auto:!1,sorted:1,min:Xt,max:-Xt,idxs:[]};function Wx(n,e,t,i,s){return e.map(r=>r==null?"":Zu(r))}function Xx(n,e,t,i,s,r,o){let a=[],l=Xs.get(s)||0;t=o?t:$t(zl(t,s),l);for(let c=t;c<=i;c=$t(c+s,l))a.push(Object.is(c,-0)?0:c);return a}function ku(n,e,t,i,s,r,o){let a=[],l=n.scales[n.axes[e].scale].log,c=l==10?ms:Gm,h=ci(c(t));s=no(l,h),l==10&&(s=xr[Li(s,xr)]);let f=t,u=s*l;l==10&&(u=xr[Li(u,xr)]);do a.push(f),f=f+s,l==10&&!Xs.has(f)&&(f=$t(f,Xs.get(s))),f>=u&&(s=f,u=s*l,l==10&&(u=xr[Li(u,xr)]));while(f<=i);return a}function $x(n,e,t,i,s,r,o){let l=n.scales[n.axes[e].scale].asinh,c=i>l?ku(n,e,qn(l,t),i,s):[l],h=i>=0&&t<=0?[0]:[];return(t<-l?ku(n,e,qn(l,-i),-t,s):[l]).reverse().map(u=>-u).concat(h,c)}var cg=/./,qx=/[12357]/,Yx=/[125]/,Am=/1/,zu=(n,e,t,i)=>n.map((s,r)=>e==4&&s==0||r%i==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function Zx(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=n.scales[o],l=n.valToPos,c=r._space,h=l(10,o),f=l(9,o)-h>=c?cg:l(7,o)-h>=c?qx:l(5,o)-h>=c?Yx:Am;if(f==Am){let u=Sn(l(1,o)-h);if(u<c)return zu(e.slice().reverse(),a.distr,f,wi(c/u)).reverse()}return zu(e,a.distr,f,1)}function Kx(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=r._space,l=n.valToPos,c=Sn(l(1,o)-l(2,o));return c<a?zu(e.slice().reverse(),3,cg,wi(a/c)).reverse():e}function Jx(n,e,t,i){return i==null?Xu:e==null?"":Zu(e)}var Rm={show:!0,scale:"y",stroke:Wu,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:ag,side:3,grid:Qu,ticks:rg,border:og,font:ef,lineGap:lg,rotate:0};function jx(n,e){let t=3+(n||1)*2;return $t(t*e,3)}function Qx(n,e){let{scale:t,idxs:i}=n.series[0],s=n._data[0],r=n.valToPos(s[i[0]],t,!0),o=n.valToPos(s[i[1]],t,!0),a=Sn(o-r),l=n.series[e],c=a/(l.points.space*Dt);return i[1]-i[0]<=c}var Cm={scale:null,auto:!0,sorted:0,min:Xt,max:-Xt},hg=(n,e,t,i,s)=>s,Im={show:!0,auto:!0,sorted:0,gaps:hg,alpha:1,facets:[yn({},Cm,{scale:"x"}),yn({},Cm,{scale:"y"})]},Pm={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:hg,alpha:1,points:{show:Qx,filter:null},values:null,min:Xt,max:-Xt,idxs:[],path:null,clip:null};function ev(n,e,t,i,s){return t/10}var ug={time:!0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},tv=yn({},ug,{time:!1,ori:1}),Lm={};function fg(n,e){let t=Lm[n];return t||(t={key:n,plots:[],sub(i){t.plots.push(i)},unsub(i){t.plots=t.plots.filter(s=>s!=i)},pub(i,s,r,o,a,l,c){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(i,s,r,o,a,l,c)}},n!=null&&(Lm[n]=t)),t}var ro=1,Gu=2;function Mr(n,e,t){let i=n.mode,s=n.series[e],r=i==2?n._data[e]:n._data,o=n.scales,a=n.bbox,l=r[0],c=i==2?r[1]:r[e],h=i==2?o[s.facets[0].scale]:o[n.series[0].scale],f=i==2?o[s.facets[1].scale]:o[s.scale],u=a.left,m=a.top,g=a.width,v=a.height,d=n.valToPosH,p=n.valToPosV;return h.ori==0?t(s,l,c,h,f,d,p,u,m,g,v,Vl,ao,Xl,pg,gg):t(s,l,c,h,f,p,d,m,u,v,g,Wl,lo,sf,mg,_g)}function tf(n,e){let t=0,i=0,s=Lt(n.bands,Ku);for(let r=0;r<s.length;r++){let o=s[r];o.series[0]==e?t=o.dir:o.series[1]==e&&(o.dir==1?i|=1:i|=2)}return[t,i==1?-1:i==2?1:i==3?2:0]}function nv(n,e,t,i,s){let r=n.mode,o=n.series[e],a=r==2?o.facets[1].scale:o.scale,l=n.scales[a];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function gs(n,e,t,i,s,r){return Mr(n,e,(o,a,l,c,h,f,u,m,g,v,d)=>{let p=o.pxRound,x=c.dir*(c.ori==0?1:-1),A=c.ori==0?ao:lo,S,C;x==1?(S=t,C=i):(S=i,C=t);let T=p(f(a[S],c,v,m)),_=p(u(l[S],h,d,g)),w=p(f(a[C],c,v,m)),U=p(u(r==1?h.max:h.min,h,d,g)),N=new Path2D(s);return A(N,w,U),A(N,T,U),A(N,T,_),N})}function Hl(n,e,t,i,s,r){let o=null;if(n.length>0){o=new Path2D;let a=e==0?Xl:sf,l=t;for(let f=0;f<n.length;f++){let u=n[f];if(u[1]>u[0]){let m=u[0]-l;m>0&&a(o,l,i,m,i+r),l=u[1]}}let c=t+s-l,h=10;c>0&&a(o,l,i-h/2,c,i+r+h)}return o}function iv(n,e,t){let i=n[n.length-1];i&&i[0]==e?i[1]=t:n.push([e,t])}function nf(n,e,t,i,s,r,o){let a=[],l=n.length;for(let c=s==1?t:i;c>=t&&c<=i;c+=s)if(e[c]===null){let f=c,u=c;if(s==1)for(;++c<=i&&e[c]===null;)u=c;else for(;--c>=t&&e[c]===null;)u=c;let m=r(n[f]),g=u==f?m:r(n[u]),v=f-s;m=o<=0&&v>=0&&v<l?r(n[v]):m;let p=u+s;g=o>=0&&p>=0&&p<l?r(n[p]):g,g>=m&&a.push([m,g])}return a}function Nm(n){return n==0?Vm:n==1?bn:e=>yr(e,n)}function dg(n){let e=n==0?Vl:Wl,t=n==0?(s,r,o,a,l,c)=>{s.arcTo(r,o,a,l,c)}:(s,r,o,a,l,c)=>{s.arcTo(o,r,l,a,c)},i=n==0?(s,r,o,a,l)=>{s.rect(r,o,a,l)}:(s,r,o,a,l)=>{s.rect(o,r,l,a)};return(s,r,o,a,l,c=0,h=0)=>{c==0&&h==0?i(s,r,o,a,l):(c=Ni(c,a/2,l/2),h=Ni(h,a/2,l/2),e(s,r+c,o),t(s,r+a,o,r+a,o+l,c),t(s,r+a,o+l,r,o+l,h),t(s,r,o+l,r,o,h),t(s,r,o,r+a,o,c),s.closePath())}}var Vl=(n,e,t)=>{n.moveTo(e,t)},Wl=(n,e,t)=>{n.moveTo(t,e)},ao=(n,e,t)=>{n.lineTo(e,t)},lo=(n,e,t)=>{n.lineTo(t,e)},Xl=dg(0),sf=dg(1),pg=(n,e,t,i,s,r)=>{n.arc(e,t,i,s,r)},mg=(n,e,t,i,s,r)=>{n.arc(t,e,i,s,r)},gg=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(e,t,i,s,r,o)},_g=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(t,e,s,i,o,r)};function yg(n){return(e,t,i,s,r)=>Mr(e,t,(o,a,l,c,h,f,u,m,g,v,d)=>{let{pxRound:p,points:x}=o,A,S;c.ori==0?(A=Vl,S=pg):(A=Wl,S=mg);let C=$t(x.width*Dt,3),T=(x.size-x.width)/2*Dt,_=$t(T*2,3),w=new Path2D,U=new Path2D,{left:N,top:R,width:G,height:B}=e.bbox;Xl(U,N-_,R-_,G+_*2,B+_*2);let L=z=>{if(l[z]!=null){let q=p(f(a[z],c,v,m)),O=p(u(l[z],h,d,g));A(w,q+T,O),S(w,q,O,T,0,Dl*2)}};if(r)r.forEach(L);else for(let z=i;z<=s;z++)L(z);return{stroke:C>0?w:null,fill:w,clip:U,flags:ro|Gu}})}function xg(n){return(e,t,i,s,r,o)=>{i!=s&&(r!=i&&o!=i&&n(e,t,i),r!=s&&o!=s&&n(e,t,s),n(e,t,o))}}var sv=xg(ao),rv=xg(lo);function vg(n){let e=Lt(n?.alignGaps,0);return(t,i,s,r)=>Mr(t,i,(o,a,l,c,h,f,u,m,g,v,d)=>{[s,r]=Bl(l,s,r);let p=o.pxRound,x=B=>p(f(B,c,v,m)),A=B=>p(u(B,h,d,g)),S,C;c.ori==0?(S=ao,C=sv):(S=lo,C=rv);let T=c.dir*(c.ori==0?1:-1),_={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:ro},w=_.stroke,U=!1;if(r-s>=v*4){let B=le=>t.posToVal(le,c.key,!0),L=null,z=null,q,O,re,X=x(a[T==1?s:r]),$=x(a[s]),W=x(a[r]),ne=B(T==1?$+1:W-1);for(let le=T==1?s:r;le>=s&&le<=r;le+=T){let Q=a[le],pe=(T==1?Q<ne:Q>ne)?X:x(Q),be=l[le];pe==X?be!=null?(O=be,L==null?(S(w,pe,A(O)),q=L=z=O):O<L?L=O:O>z&&(z=O)):be===null&&(U=!0):(L!=null&&C(w,X,A(L),A(z),A(q),A(O)),be!=null?(O=be,S(w,pe,A(O)),L=z=q=O):(L=z=null,be===null&&(U=!0)),X=pe,ne=B(X+T))}L!=null&&L!=z&&re!=X&&C(w,X,A(L),A(z),A(q),A(O))}else for(let B=T==1?s:r;B>=s&&B<=r;B+=T){let L=l[B];L===null?U=!0:L!=null&&S(w,x(a[B]),A(L))}let[R,G]=tf(t,i);if(o.fill!=null||R!=0){let B=_.fill=new Path2D(w),L=o.fillTo(t,i,o.min,o.max,R),z=A(L),q=x(a[s]),O=x(a[r]);T==-1&&([O,q]=[q,O]),S(B,O,z),S(B,q,z)}if(!o.spanGaps){let B=[];U&&B.push(...nf(a,l,s,r,T,x,e)),_.gaps=B=o.gaps(t,i,s,r,B),_.clip=Hl(B,c.ori,m,g,v,d)}return G!=0&&(_.band=G==2?[gs(t,i,s,r,w,-1),gs(t,i,s,r,w,1)]:gs(t,i,s,r,w,G)),_})}function ov(n){let e=Lt(n.align,1),t=Lt(n.ascDesc,!1),i=Lt(n.alignGaps,0),s=Lt(n.extend,!1);return(r,o,a,l)=>Mr(r,o,(c,h,f,u,m,g,v,d,p,x,A)=>{[a,l]=Bl(f,a,l);let S=c.pxRound,{left:C,width:T}=r.bbox,_=$=>S(g($,u,x,d)),w=$=>S(v($,m,A,p)),U=u.ori==0?ao:lo,N={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:ro},R=N.stroke,G=u.dir*(u.ori==0?1:-1),B=w(f[G==1?a:l]),L=_(h[G==1?a:l]),z=L,q=L;s&&e==-1&&(q=C,U(R,q,B)),U(R,L,B);for(let $=G==1?a:l;$>=a&&$<=l;$+=G){let W=f[$];if(W==null)continue;let ne=_(h[$]),le=w(W);e==1?U(R,ne,B):U(R,z,le),U(R,ne,le),B=le,z=ne}let O=z;s&&e==1&&(O=C+T,U(R,O,B));let[re,X]=tf(r,o);if(c.fill!=null||re!=0){let $=N.fill=new Path2D(R),W=c.fillTo(r,o,c.min,c.max,re),ne=w(W);U($,O,ne),U($,q,ne)}if(!c.spanGaps){let $=[];$.push(...nf(h,f,a,l,G,_,i));let W=c.width*Dt/2,ne=t||e==1?W:-W,le=t||e==-1?-W:W;$.forEach(Q=>{Q[0]+=ne,Q[1]+=le}),N.gaps=$=c.gaps(r,o,a,l,$),N.clip=Hl($,u.ori,d,p,x,A)}return X!=0&&(N.band=X==2?[gs(r,o,a,l,R,-1),gs(r,o,a,l,R,1)]:gs(r,o,a,l,R,X)),N})}function Dm(n,e,t,i,s,r,o=Xt){if(n.length>1){let a=null;for(let l=0,c=1/0;l<n.length;l++)if(e[l]!==void 0){if(a!=null){let h=Sn(n[l]-n[a]);h<c&&(c=h,o=Sn(t(n[l],i,s,r)-t(n[a],i,s,r)))}a=l}}return o}function av(n){n=n||da;let e=Lt(n.size,[.6,Xt,1]),t=n.align||0,i=n.gap||0,s=n.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;let r=Tt(s),o=1-e[0],a=Lt(e[1],Xt),l=Lt(e[2],1),c=Lt(n.disp,da),h=Lt(n.each,m=>{}),{fill:f,stroke:u}=c;return(m,g,v,d)=>Mr(m,g,(p,x,A,S,C,T,_,w,U,N,R)=>{let G=p.pxRound,B=t,L=i*Dt,z=a*Dt,q=l*Dt,O,re;S.ori==0?[O,re]=r(m,g):[re,O]=r(m,g);let X=S.dir*(S.ori==0?1:-1),$=S.ori==0?Xl:sf,W=S.ori==0?h:(ge,Ke,dt,Ae,Wt,Xe,Je)=>{h(ge,Ke,dt,Wt,Ae,Je,Xe)},ne=Lt(m.bands,Ku).find(ge=>ge.series[0]==g),le=ne!=null?ne.dir:0,Q=p.fillTo(m,g,p.min,p.max,le),me=G(_(Q,C,R,U)),pe,be,xe,We=N,Qe=G(p.width*Dt),Ne=!1,qe=null,tt=null,fe=null,ke=null;f!=null&&(Qe==0||u!=null)&&(Ne=!0,qe=f.values(m,g,v,d),tt=new Map,new Set(qe).forEach(ge=>{ge!=null&&tt.set(ge,new Path2D)}),Qe>0&&(fe=u.values(m,g,v,d),ke=new Map,new Set(fe).forEach(ge=>{ge!=null&&ke.set(ge,new Path2D)})));let{x0:Ze,size:Rt}=c;if(Ze!=null&&Rt!=null){B=1,x=Ze.values(m,g,v,d),Ze.unit==2&&(x=x.map(dt=>m.posToVal(w+dt*N,S.key,!0)));let ge=Rt.values(m,g,v,d);Rt.unit==2?be=ge[0]*N:be=T(ge[0],S,N,w)-T(0,S,N,w),We=Dm(x,A,T,S,N,w,We),xe=We-be+L}else We=Dm(x,A,T,S,N,w,We),xe=We*o+L,be=We-xe;xe<1&&(xe=0),Qe>=be/2&&(Qe=0),xe<5&&(G=Vm);let wt=xe>0,Vt=We-xe-(wt?Qe:0);be=G(Bu(Vt,q,z)),pe=(B==0?be/2:B==X?0:be)-B*X*((B==0?L/2:0)+(wt?Qe/2:0));let et={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},Ct=Ne?null:new Path2D,ut=null;if(ne!=null)ut=m.data[ne.series[1]];else{let{y0:ge,y1:Ke}=c;ge!=null&&Ke!=null&&(A=Ke.values(m,g,v,d),ut=ge.values(m,g,v,d))}let ft=O*be,F=re*be;for(let ge=X==1?v:d;ge>=v&&ge<=d;ge+=X){let Ke=A[ge];if(Ke==null)continue;if(ut!=null){let Y=ut[ge]??0;if(Ke-Y==0)continue;me=_(Y,C,R,U)}let dt=S.distr!=2||c!=null?x[ge]:ge,Ae=T(dt,S,N,w),Wt=_(Lt(Ke,Q),C,R,U),Xe=G(Ae-pe),Je=G(qn(Wt,me)),I=G(Ni(Wt,me)),b=Je-I;if(Ke!=null){let Y=Ke<0?F:ft,de=Ke<0?ft:F;Ne?(Qe>0&&fe[ge]!=null&&$(ke.get(fe[ge]),Xe,I+ci(Qe/2),be,qn(0,b-Qe),Y,de),qe[ge]!=null&&$(tt.get(qe[ge]),Xe,I+ci(Qe/2),be,qn(0,b-Qe),Y,de)):$(Ct,Xe,I+ci(Qe/2),be,qn(0,b-Qe),Y,de),W(m,g,ge,Xe-Qe/2,I,be+Qe,b)}}return Qe>0?et.stroke=Ne?ke:Ct:Ne||(et._fill=p.width==0?p._fill:p._stroke??p._fill,et.width=0),et.fill=Ne?tt:Ct,et})}function lv(n,e){let t=Lt(e?.alignGaps,0);return(i,s,r,o)=>Mr(i,s,(a,l,c,h,f,u,m,g,v,d,p)=>{[r,o]=Bl(c,r,o);let x=a.pxRound,A=O=>x(u(O,h,d,g)),S=O=>x(m(O,f,p,v)),C,T,_;h.ori==0?(C=Vl,_=ao,T=gg):(C=Wl,_=lo,T=_g);let w=h.dir*(h.ori==0?1:-1),U=A(l[w==1?r:o]),N=U,R=[],G=[];for(let O=w==1?r:o;O>=r&&O<=o;O+=w)if(c[O]!=null){let X=l[O],$=A(X);R.push(N=$),G.push(S(c[O]))}let B={stroke:n(R,G,C,_,T,x),fill:null,clip:null,band:null,gaps:null,flags:ro},L=B.stroke,[z,q]=tf(i,s);if(a.fill!=null||z!=0){let O=B.fill=new Path2D(L),re=a.fillTo(i,s,a.min,a.max,z),X=S(re);_(O,N,X),_(O,U,X)}if(!a.spanGaps){let O=[];O.push(...nf(l,c,r,o,w,A,t)),B.gaps=O=a.gaps(i,s,r,o,O),B.clip=Hl(O,h.ori,g,v,d,p)}return q!=0&&(B.band=q==2?[gs(i,s,r,o,L,-1),gs(i,s,r,o,L,1)]:gs(i,s,r,o,L,q)),B})}function cv(n){return lv(hv,n)}function hv(n,e,t,i,s,r){let o=n.length;if(o<2)return null;let a=new Path2D;if(t(a,n[0],e[0]),o==2)i(a,n[1],e[1]);else{let l=Array(o),c=Array(o-1),h=Array(o-1),f=Array(o-1);for(let u=0;u<o-1;u++)h[u]=e[u+1]-e[u],f[u]=n[u+1]-n[u],c[u]=h[u]/f[u];l[0]=c[0];for(let u=1;u<o-1;u++)c[u]===0||c[u-1]===0||c[u-1]>0!=c[u]>0?l[u]=0:(l[u]=3*(f[u-1]+f[u])/((2*f[u]+f[u-1])/c[u-1]+(f[u]+2*f[u-1])/c[u]),isFinite(l[u])||(l[u]=0));l[o-1]=c[o-2];for(let u=0;u<o-1;u++)s(a,n[u]+f[u]/3,e[u]+l[u]*f[u]/3,n[u+1]-f[u]/3,e[u+1]-l[u+1]*f[u]/3,n[u+1],e[u+1])}return a}var Hu=new Set;function Um(){for(let n of Hu)n.syncRect(!0)}oo&&(br(Wy,to,Um),br(Xy,to,Um,!0),br(Ul,to,()=>{Pn.pxRatio=Dt}));var uv=vg(),fv=yg();function Om(n,e,t,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((r,o)=>Vu(r,o,e,t))}function dv(n,e){return n.map((t,i)=>i==0?{}:yn({},e,t))}function Vu(n,e,t,i){return yn({},e==0?t:i,n)}function bg(n,e,t){return e==null?io:[e,t]}var pv=bg;function mv(n,e,t){return e==null?io:Ol(e,t,Yu,!0)}function Sg(n,e,t,i){return e==null?io:kl(e,t,n.scales[i].log,!1)}var gv=Sg;function Mg(n,e,t,i){return e==null?io:qu(e,t,n.scales[i].log,!1)}var _v=Mg;function yv(n,e,t,i,s){let r=qn(pm(n),pm(e)),o=e-n,a=Li(s/i*o,t);do{let l=t[a],c=i*l/o;if(c>=s&&r+(l<5?Xs.get(l):0)<=17)return[l,c]}while(++a<t.length);return[0,0]}function Fm(n){let e,t;return n=n.replace(/(\d+)px/,(i,s)=>(e=bn((t=+s)*Dt))+"px"),[n,e,t]}function xv(n){n.show&&[n.font,n.labelFont].forEach(e=>{let t=$t(e[2]*Dt,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Pn(n,e,t){let i={mode:Lt(n.mode,1)},s=i.mode;function r(y,M,P,D){let V=M.valToPct(y);return D+P*(M.dir==-1?1-V:V)}function o(y,M,P,D){let V=M.valToPct(y);return D+P*(M.dir==-1?V:1-V)}function a(y,M,P,D){return M.ori==0?r(y,M,P,D):o(y,M,P,D)}i.valToPosH=r,i.valToPosV=o;let l=!1;i.status=0;let c=i.root=Mi(Ty);if(n.id!=null&&(c.id=n.id),li(c,n.class),n.title){let y=Mi(Cy,c);y.textContent=n.title}let h=Pi("canvas"),f=i.ctx=h.getContext("2d"),u=Mi(Iy,c);br("click",u,y=>{y.target===g&&(Yt!=Vr||en!=Wr)&&Un.click(i,y)},!0);let m=i.under=Mi(Py,u);u.appendChild(h);let g=i.over=Mi(Ly,u);n=so(n);let v=+Lt(n.pxAlign,1),d=Nm(v);(n.plugins||[]).forEach(y=>{y.opts&&(n=y.opts(i,n)||n)});let p=n.ms||.001,x=i.series=s==1?Om(n.series||[],Tm,Pm,!1):dv(n.series||[null],Im),A=i.axes=Om(n.axes||[],Em,Rm,!0),S=i.scales={},C=i.bands=n.bands||[];C.forEach(y=>{y.fill=Tt(y.fill||null),y.dir=Lt(y.dir,-1)});let T=s==2?x[1].facets[0].scale:x[0].scale,_={axes:hs,series:vt},w=(n.drawOrder||["axes","series"]).map(y=>_[y]);function U(y){let M=y.distr==3?P=>ms(P>0?P:y.clamp(i,P,y.min,y.max,y.key)):y.distr==4?P=>Iu(P,y.asinh):y.distr==100?P=>y.fwd(P):P=>P;return P=>{let D=M(P),{_min:V,_max:j}=y,he=j-V;return(D-V)/he}}function N(y){let M=S[y];if(M==null){let P=(n.scales||da)[y]||da;if(P.from!=null){N(P.from);let D=yn({},S[P.from],P,{key:y});D.valToPct=U(D),S[y]=D}else{M=S[y]=yn({},y==T?ug:tv,P),M.key=y;let D=M.time,V=M.range,j=Ws(V);if((y!=T||s==2&&!D)&&(j&&(V[0]==null||V[1]==null)&&(V={min:V[0]==null?um:{mode:1,hard:V[0],soft:V[0]},max:V[1]==null?um:{mode:1,hard:V[1],soft:V[1]}},j=!1),!j&&Gl(V))){let he=V;V=(_e,Ee,Oe)=>Ee==null?io:Ol(Ee,Oe,he)}M.range=Tt(V||(D?pv:y==T?M.distr==3?gv:M.distr==4?_v:bg:M.distr==3?Sg:M.distr==4?Mg:mv)),M.auto=Tt(j?!1:M.auto),M.clamp=Tt(M.clamp||ev),M._min=M._max=null,M.valToPct=U(M)}}}N("x"),N("y"),s==1&&x.forEach(y=>{N(y.scale)}),A.forEach(y=>{N(y.scale)});for(let y in n.scales)N(y);let R=S[T],G=R.distr,B,L;R.ori==0?(li(c,Ay),B=r,L=o):(li(c,Ry),B=o,L=r);let z={};for(let y in S){let M=S[y];(M.min!=null||M.max!=null)&&(z[y]={min:M.min,max:M.max},M.min=M.max=null)}let q=n.tzDate||(y=>new Date(bn(y/p))),O=n.fmtDate||Ju,re=p==1?Ax(q):Ix(q),X=Sm(q,bm(p==1?Tx:Cx,O)),$=wm(q,Mm(Lx,O)),W=[],ne=i.legend=yn({},Ux,n.legend),le=i.cursor=yn({},Gx,{drag:{y:s==2}},n.cursor),Q=ne.show,me=le.show,pe=ne.markers;ne.idxs=W,pe.width=Tt(pe.width),pe.dash=Tt(pe.dash),pe.stroke=Tt(pe.stroke),pe.fill=Tt(pe.fill);let be,xe,We,Qe=[],Ne=[],qe,tt=!1,fe={};if(ne.live){let y=x[1]?x[1].values:null;tt=y!=null,qe=tt?y(i,1,0):{_:0};for(let M in qe)fe[M]=Xu}if(Q)if(be=Pi("table",By,c),We=Pi("tbody",null,be),ne.mount(i,be),tt){xe=Pi("thead",null,be,We);let y=Pi("tr",null,xe);Pi("th",null,y);for(var ke in qe)Pi("th",jp,y).textContent=ke}else li(be,zy),ne.live&&li(be,ky);let Ze={show:!0},Rt={show:!1};function wt(y,M){if(M==0&&(tt||!ne.live||s==2))return io;let P=[],D=Pi("tr",Gy,We,We.childNodes[M]);li(D,y.class),y.show||li(D,vr);let V=Pi("th",null,D);if(pe.show){let _e=Mi(Hy,V);if(M>0){let Ee=pe.width(i,M);Ee&&(_e.style.border=Ee+"px "+pe.dash(i,M)+" "+pe.stroke(i,M)),_e.style.background=pe.fill(i,M)}}let j=Mi(jp,V);y.label instanceof HTMLElement?j.appendChild(y.label):j.textContent=y.label,M>0&&(pe.show||(j.style.color=y.width>0?pe.stroke(i,M):pe.fill(i,M)),et("click",V,_e=>{if(le._lock)return;st(_e);let Ee=x.indexOf(y);if((_e.ctrlKey||_e.metaKey)!=ne.isolate){let Oe=x.some((Fe,ze)=>ze>0&&ze!=Ee&&Fe.show);x.forEach((Fe,ze)=>{ze>0&&$i(ze,Oe?ze==Ee?Ze:Rt:Ze,!0,mn.setSeries)})}else $i(Ee,{show:!y.show},!0,mn.setSeries)},!1),rt&&et(nm,V,_e=>{le._lock||(st(_e),$i(x.indexOf(y),$r,!0,mn.setSeries))},!1));for(var he in qe){let _e=Pi("td",Vy,D);_e.textContent="--",P.push(_e)}return[D,P]}let Vt=new Map;function et(y,M,P,D=!0){let V=Vt.get(M)||{},j=le.bind[y](i,M,P,D);j&&(br(y,M,V[y]=j),Vt.set(M,V))}function Ct(y,M,P){let D=Vt.get(M)||{};for(let V in D)(y==null||V==y)&&(Fu(V,M,D[V]),delete D[V]);y==null&&Vt.delete(M)}let ut=0,ft=0,F=0,ge=0,Ke=0,dt=0,Ae=Ke,Wt=dt,Xe=F,Je=ge,I=0,b=0,Y=0,de=0;i.bbox={};let ce=!1,Me=!1,we=!1,ie=!1,oe=!1,ye=!1;function k(y,M,P){(P||y!=i.width||M!=i.height)&&ae(y,M),gt(!1),we=!0,Me=!0,Fn()}function ae(y,M){i.width=ut=F=y,i.height=ft=ge=M,Ke=dt=0,Te(),$e();let P=i.bbox;I=P.left=yr(Ke*Dt,.5),b=P.top=yr(dt*Dt,.5),Y=P.width=yr(F*Dt,.5),de=P.height=yr(ge*Dt,.5)}let se=3;function Re(){let y=!1,M=0;for(;!y;){M++;let P=zr(M),D=Xi(M);y=M==se||P&&D,y||(ae(i.width,i.height),Me=!0)}}function Se({width:y,height:M}){k(y,M)}i.setSize=Se;function Te(){let y=!1,M=!1,P=!1,D=!1;A.forEach((V,j)=>{if(V.show&&V._show){let{side:he,_size:_e}=V,Ee=he%2,Oe=V.label!=null?V.labelSize:0,Fe=_e+Oe;Fe>0&&(Ee?(F-=Fe,he==3?(Ke+=Fe,D=!0):P=!0):(ge-=Fe,he==0?(dt+=Fe,y=!0):M=!0))}}),Vi[0]=y,Vi[1]=P,Vi[2]=M,Vi[3]=D,F-=Ai[1]+Ai[3],Ke+=Ai[3],ge-=Ai[2]+Ai[0],dt+=Ai[0]}function $e(){let y=Ke+F,M=dt+ge,P=Ke,D=dt;function V(j,he){switch(j){case 1:return y+=he,y-he;case 2:return M+=he,M-he;case 3:return P-=he,P+he;case 0:return D-=he,D+he}}A.forEach((j,he)=>{if(j.show&&j._show){let _e=j.side;j._pos=V(_e,j._size),j.label!=null&&(j._lpos=V(_e,j.labelSize))}})}if(le.dataIdx==null){let y=le.hover,M=y.skip=new Set(y.skip??[]);M.add(void 0);let P=y.prox=Tt(y.prox),D=y.bias??=0;le.dataIdx=(V,j,he,_e)=>{if(j==0)return he;let Ee=he,Oe=P(V,j,he,_e)??Xt,Fe=Oe>=0&&Oe<Xt,ze=R.ori==0?F:ge,ct=le.left,Nt=e[0],Pt=e[j];if(M.has(Pt[he])){Ee=null;let St=null,it=null,Ye;if(D==0||D==-1)for(Ye=he;St==null&&Ye-- >0;)M.has(Pt[Ye])||(St=Ye);if(D==0||D==1)for(Ye=he;it==null&&Ye++<Pt.length;)M.has(Pt[Ye])||(it=Ye);if(St!=null||it!=null)if(Fe){let Kt=St==null?-1/0:B(Nt[St],R,ze,0),ln=it==null?1/0:B(Nt[it],R,ze,0),Cn=ct-Kt,Gt=ln-ct;Cn<=Gt?Cn<=Oe&&(Ee=St):Gt<=Oe&&(Ee=it)}else Ee=it==null?St:St==null?it:he-St<=it-he?St:it}else Fe&&Sn(ct-B(Nt[he],R,ze,0))>Oe&&(Ee=null);return Ee}}let st=y=>{le.event=y};le.idxs=W,le._lock=!1;let ue=le.points;ue.show=Tt(ue.show),ue.size=Tt(ue.size),ue.stroke=Tt(ue.stroke),ue.width=Tt(ue.width),ue.fill=Tt(ue.fill);let Ge=i.focus=yn({},n.focus||{alpha:.3},le.focus),rt=Ge.prox>=0,Pe=rt&&ue.one,mt=[],qt=[],Hn=[];function Ho(y,M){let P=ue.show(i,M);if(P instanceof HTMLElement)return li(P,Fy),li(P,y.class),ji(P,-10,-10,F,ge),g.insertBefore(P,mt[M]),P}function Fr(y,M){if(s==1||M>0){let P=s==1&&S[y.scale].time,D=y.value;y.value=P?_m(D)?wm(q,Mm(D,O)):D||$:D||Jx,y.label=y.label||(P?Vx:Hx)}if(Pe||M>0){y.width=y.width==null?1:y.width,y.paths=y.paths||uv||tx,y.fillTo=Tt(y.fillTo||nv),y.pxAlign=+Lt(y.pxAlign,v),y.pxRound=Nm(y.pxAlign),y.stroke=Tt(y.stroke||null),y.fill=Tt(y.fill||null),y._stroke=y._fill=y._paths=y._focus=null;let P=jx(qn(1,y.width),1),D=y.points=yn({},{size:P,width:qn(1,P*.2),stroke:y.stroke,space:P*2,paths:fv,_stroke:null,_fill:null},y.points);D.show=Tt(D.show),D.filter=Tt(D.filter),D.fill=Tt(D.fill),D.stroke=Tt(D.stroke),D.paths=Tt(D.paths),D.pxAlign=y.pxAlign}if(Q){let P=wt(y,M);Qe.splice(M,0,P[0]),Ne.splice(M,0,P[1]),ne.values.push(null)}if(me){W.splice(M,0,null);let P=null;Pe?M==0&&(P=Ho(y,M)):M>0&&(P=Ho(y,M)),mt.splice(M,0,P),qt.splice(M,0,0),Hn.splice(M,0,0)}Rn("addSeries",M)}function Kh(y,M){M=M??x.length,y=s==1?Vu(y,M,Tm,Pm):Vu(y,M,{},Im),x.splice(M,0,y),Fr(x[M],M)}i.addSeries=Kh;function sl(y){if(x.splice(y,1),Q){ne.values.splice(y,1),Ne.splice(y,1);let M=Qe.splice(y,1)[0];Ct(null,M.firstChild),M.remove()}me&&(W.splice(y,1),mt.splice(y,1)[0].remove(),qt.splice(y,1),Hn.splice(y,1)),Rn("delSeries",y)}i.delSeries=sl;let Vi=[!1,!1,!1,!1];function as(y,M){if(y._show=y.show,y.show){let P=y.side%2,D=S[y.scale];D==null&&(y.scale=P?x[1].scale:T,D=S[y.scale]);let V=D.time;y.size=Tt(y.size),y.space=Tt(y.space),y.rotate=Tt(y.rotate),Ws(y.incrs)&&y.incrs.forEach(he=>{!Xs.has(he)&&Xs.set(he,$m(he))}),y.incrs=Tt(y.incrs||(D.distr==2?Mx:V?p==1?Ex:Rx:xr)),y.splits=Tt(y.splits||(V&&D.distr==1?re:D.distr==3?ku:D.distr==4?$x:Xx)),y.stroke=Tt(y.stroke),y.grid.stroke=Tt(y.grid.stroke),y.ticks.stroke=Tt(y.ticks.stroke),y.border.stroke=Tt(y.border.stroke);let j=y.values;y.values=Ws(j)&&!Ws(j[0])?Tt(j):V?Ws(j)?Sm(q,bm(j,O)):_m(j)?Px(q,j):j||X:j||Wx,y.filter=Tt(y.filter||(D.distr>=3&&D.log==10?Zx:D.distr==3&&D.log==2?Kx:Wm)),y.font=Fm(y.font),y.labelFont=Fm(y.labelFont),y._size=y.size(i,null,M,0),y._space=y._rotate=y._incrs=y._found=y._splits=y._values=null,y._size>0&&(Vi[M]=!0,y._el=Mi(Ny,u))}}function ls(y,M,P,D){let[V,j,he,_e]=P,Ee=M%2,Oe=0;return Ee==0&&(_e||j)&&(Oe=M==0&&!V||M==2&&!he?bn(Em.size/3):0),Ee==1&&(V||he)&&(Oe=M==1&&!j||M==3&&!_e?bn(Rm.size/2):0),Oe}let Vo=i.padding=(n.padding||[ls,ls,ls,ls]).map(y=>Tt(Lt(y,ls))),Ai=i._padding=Vo.map((y,M)=>y(i,M,Vi,0)),on,hn=null,un=null,Wi=s==1?x[0].idxs:null,ii=null,Is=!1;function Wo(y,M){if(e=y??[],i.data=i._data=e,s==2){on=0;for(let P=1;P<x.length;P++)on+=e[P][0].length}else{e.length==0&&(i.data=i._data=e=[[]]),ii=e[0],on=ii.length;let P=e;if(G==2){P=e.slice();let D=P[0]=Array(on);for(let V=0;V<on;V++)D[V]=V}i._data=e=P}if(gt(!0),Rn("setData"),G==2&&(we=!0),M!==!1){let P=R;P.auto(i,Is)?Xo():Ns(T,P.min,P.max),ie=ie||le.left>=0,ye=!0,Fn()}}i.setData=Wo;function Xo(){Is=!0;let y,M;s==1&&(on>0?(hn=Wi[0]=0,un=Wi[1]=on-1,y=e[0][hn],M=e[0][un],G==2?(y=hn,M=un):y==M&&(G==3?[y,M]=kl(y,y,R.log,!1):G==4?[y,M]=qu(y,y,R.log,!1):R.time?M=y+bn(86400/p):[y,M]=Ol(y,M,Yu,!0))):(hn=Wi[0]=y=null,un=Wi[1]=M=null)),Ns(T,y,M)}let Br,Ps,kr,E,H,ee,Z,K,Ce,Le;function Ie(y,M,P,D,V,j){y??=em,P??=Ku,D??="butt",V??=em,j??="round",y!=Br&&(f.strokeStyle=Br=y),V!=Ps&&(f.fillStyle=Ps=V),M!=kr&&(f.lineWidth=kr=M),j!=H&&(f.lineJoin=H=j),D!=ee&&(f.lineCap=ee=D),P!=E&&f.setLineDash(E=P)}function De(y,M,P,D){M!=Ps&&(f.fillStyle=Ps=M),y!=Z&&(f.font=Z=y),P!=K&&(f.textAlign=K=P),D!=Ce&&(f.textBaseline=Ce=D)}function Ve(y,M,P,D,V=0){if(D.length>0&&y.auto(i,Is)&&(M==null||M.min==null)){let j=Lt(hn,0),he=Lt(un,D.length-1),_e=P.min==null?Zy(D,j,he,V,y.distr==3):[P.min,P.max];y.min=Ni(y.min,P.min=_e[0]),y.max=qn(y.max,P.max=_e[1])}}let ot={min:null,max:null};function xt(){for(let D in S){let V=S[D];z[D]==null&&(V.min==null||z[T]!=null&&V.auto(i,Is))&&(z[D]=ot)}for(let D in S){let V=S[D];z[D]==null&&V.from!=null&&z[V.from]!=null&&(z[D]=ot)}z[T]!=null&&gt(!0);let y={};for(let D in z){let V=z[D];if(V!=null){let j=y[D]=so(S[D],sx);if(V.min!=null)yn(j,V);else if(D!=T||s==2)if(on==0&&j.from==null){let he=j.range(i,null,null,D);j.min=he[0],j.max=he[1]}else j.min=Xt,j.max=-Xt}}if(on>0){x.forEach((D,V)=>{if(s==1){let j=D.scale,he=z[j];if(he==null)return;let _e=y[j];if(V==0){let Ee=_e.range(i,_e.min,_e.max,j);_e.min=Ee[0],_e.max=Ee[1],hn=Li(_e.min,e[0]),un=Li(_e.max,e[0]),un-hn>1&&(e[0][hn]<_e.min&&hn++,e[0][un]>_e.max&&un--),D.min=ii[hn],D.max=ii[un]}else D.show&&D.auto&&Ve(_e,he,D,e[V],D.sorted);D.idxs[0]=hn,D.idxs[1]=un}else if(V>0&&D.show&&D.auto){let[j,he]=D.facets,_e=j.scale,Ee=he.scale,[Oe,Fe]=e[V],ze=y[_e],ct=y[Ee];ze!=null&&Ve(ze,z[_e],j,Oe,j.sorted),ct!=null&&Ve(ct,z[Ee],he,Fe,he.sorted),D.min=he.min,D.max=he.max}});for(let D in y){let V=y[D],j=z[D];if(V.from==null&&(j==null||j.min==null)){let he=V.range(i,V.min==Xt?null:V.min,V.max==-Xt?null:V.max,D);V.min=he[0],V.max=he[1]}}}for(let D in y){let V=y[D];if(V.from!=null){let j=y[V.from];if(j.min==null)V.min=V.max=null;else{let he=V.range(i,j.min,j.max,D);V.min=he[0],V.max=he[1]}}}let M={},P=!1;for(let D in y){let V=y[D],j=S[D];if(j.min!=V.min||j.max!=V.max){j.min=V.min,j.max=V.max;let he=j.distr;j._min=he==3?ms(j.min):he==4?Iu(j.min,j.asinh):he==100?j.fwd(j.min):j.min,j._max=he==3?ms(j.max):he==4?Iu(j.max,j.asinh):he==100?j.fwd(j.max):j.max,M[D]=P=!0}}if(P){x.forEach((D,V)=>{s==2?V>0&&M.y&&(D._paths=null):M[D.scale]&&(D._paths=null)});for(let D in M)we=!0,Rn("setScale",D);me&&le.left>=0&&(ie=ye=!0)}for(let D in z)z[D]=null}function He(y){let M=Bu(hn-1,0,on-1),P=Bu(un+1,0,on-1);for(;y[M]==null&&M>0;)M--;for(;y[P]==null&&P<on-1;)P++;return[M,P]}function vt(){if(on>0){let y=x.some(M=>M._focus)&&Le!=Ge.alpha;y&&(f.globalAlpha=Le=Ge.alpha),x.forEach((M,P)=>{if(P>0&&M.show&&(nn(P,!1),nn(P,!0),M._paths==null)){let D=Le;Le!=M.alpha&&(f.globalAlpha=Le=M.alpha);let V=s==2?[0,e[P][0].length-1]:He(e[P]);M._paths=M.paths(i,P,V[0],V[1]),Le!=D&&(f.globalAlpha=Le=D)}}),x.forEach((M,P)=>{if(P>0&&M.show){let D=Le;Le!=M.alpha&&(f.globalAlpha=Le=M.alpha),M._paths!=null&&Bt(P,!1);{let V=M._paths!=null?M._paths.gaps:null,j=M.points.show(i,P,hn,un,V),he=M.points.filter(i,P,j,V);(j||he)&&(M.points._paths=M.points.paths(i,P,hn,un,he),Bt(P,!0))}Le!=D&&(f.globalAlpha=Le=D),Rn("drawSeries",P)}}),y&&(f.globalAlpha=Le=1)}}function nn(y,M){let P=M?x[y].points:x[y];P._stroke=P.stroke(i,y),P._fill=P.fill(i,y)}function Bt(y,M){let P=M?x[y].points:x[y],{stroke:D,fill:V,clip:j,flags:he,_stroke:_e=P._stroke,_fill:Ee=P._fill,_width:Oe=P.width}=P._paths;Oe=$t(Oe*Dt,3);let Fe=null,ze=Oe%2/2;M&&Ee==null&&(Ee=Oe>0?"#fff":_e);let ct=P.pxAlign==1&&ze>0;if(ct&&f.translate(ze,ze),!M){let Nt=I-Oe/2,Pt=b-Oe/2,St=Y+Oe,it=de+Oe;Fe=new Path2D,Fe.rect(Nt,Pt,St,it)}M?Be(_e,Oe,P.dash,P.cap,Ee,D,V,he,j):kt(y,_e,Oe,P.dash,P.cap,Ee,D,V,he,Fe,j),ct&&f.translate(-ze,-ze)}function kt(y,M,P,D,V,j,he,_e,Ee,Oe,Fe){let ze=!1;Ee!=0&&C.forEach((ct,Nt)=>{if(ct.series[0]==y){let Pt=x[ct.series[1]],St=e[ct.series[1]],it=(Pt._paths||da).band;Ws(it)&&(it=ct.dir==1?it[0]:it[1]);let Ye,Kt=null;Pt.show&&it&&Jy(St,hn,un)?(Kt=ct.fill(i,Nt)||j,Ye=Pt._paths.clip):it=null,Be(M,P,D,V,Kt,he,_e,Ee,Oe,Fe,Ye,it),ze=!0}}),ze||Be(M,P,D,V,j,he,_e,Ee,Oe,Fe)}let vn=ro|Gu;function Be(y,M,P,D,V,j,he,_e,Ee,Oe,Fe,ze){Ie(y,M,P,D,V),(Ee||Oe||ze)&&(f.save(),Ee&&f.clip(Ee),Oe&&f.clip(Oe)),ze?(_e&vn)==vn?(f.clip(ze),Fe&&f.clip(Fe),Et(V,he),fn(y,j,M)):_e&Gu?(Et(V,he),f.clip(ze),fn(y,j,M)):_e&ro&&(f.save(),f.clip(ze),Fe&&f.clip(Fe),Et(V,he),f.restore(),fn(y,j,M)):(Et(V,he),fn(y,j,M)),(Ee||Oe||ze)&&f.restore()}function fn(y,M,P){P>0&&(M instanceof Map?M.forEach((D,V)=>{f.strokeStyle=Br=V,f.stroke(D)}):M!=null&&y&&f.stroke(M))}function Et(y,M){M instanceof Map?M.forEach((P,D)=>{f.fillStyle=Ps=D,f.fill(P)}):M!=null&&y&&f.fill(M)}function cs(y,M,P,D){let V=A[y],j;if(D<=0)j=[0,0];else{let he=V._space=V.space(i,y,M,P,D),_e=V._incrs=V.incrs(i,y,M,P,D,he);j=yv(M,P,_e,D,he)}return V._found=j}function dn(y,M,P,D,V,j,he,_e,Ee,Oe){let Fe=he%2/2;v==1&&f.translate(Fe,Fe),Ie(_e,he,Ee,Oe,_e),f.beginPath();let ze,ct,Nt,Pt,St=V+(D==0||D==3?-j:j);P==0?(ct=V,Pt=St):(ze=V,Nt=St);for(let it=0;it<y.length;it++)M[it]!=null&&(P==0?ze=Nt=y[it]:ct=Pt=y[it],f.moveTo(ze,ct),f.lineTo(Nt,Pt));f.stroke(),v==1&&f.translate(-Fe,-Fe)}function zr(y){let M=!0;return A.forEach((P,D)=>{if(!P.show)return;let V=S[P.scale];if(V.min==null){P._show&&(M=!1,P._show=!1,gt(!1));return}else P._show||(M=!1,P._show=!0,gt(!1));let j=P.side,he=j%2,{min:_e,max:Ee}=V,[Oe,Fe]=cs(D,_e,Ee,he==0?F:ge);if(Fe==0)return;let ze=V.distr==2,ct=P._splits=P.splits(i,D,_e,Ee,Oe,Fe,ze),Nt=V.distr==2?ct.map(Ye=>ii[Ye]):ct,Pt=V.distr==2?ii[ct[1]]-ii[ct[0]]:Oe,St=P._values=P.values(i,P.filter(i,Nt,D,Fe,Pt),D,Fe,Pt);P._rotate=j==2?P.rotate(i,St,D,Fe):0;let it=P._size;P._size=wi(P.size(i,St,D,y)),it!=null&&P._size!=it&&(M=!1)}),M}function Xi(y){let M=!0;return Vo.forEach((P,D)=>{let V=P(i,D,Vi,y);V!=Ai[D]&&(M=!1),Ai[D]=V}),M}function hs(){for(let y=0;y<A.length;y++){let M=A[y];if(!M.show||!M._show)continue;let P=M.side,D=P%2,V,j,he=M.stroke(i,y),_e=P==0||P==3?-1:1,[Ee,Oe]=M._found;if(M.label!=null){let Xn=M.labelGap*_e,oi=bn((M._lpos+Xn)*Dt);De(M.labelFont[0],he,"center",P==2?"top":Qp),f.save(),D==1?(V=j=0,f.translate(oi,bn(b+de/2)),f.rotate((P==3?-Dl:Dl)/2)):(V=bn(I+Y/2),j=oi);let fr=Hm(M.label)?M.label(i,y,Ee,Oe):M.label;f.fillText(fr,V,j),f.restore()}if(Oe==0)continue;let Fe=S[M.scale],ze=D==0?Y:de,ct=D==0?I:b,Nt=M._splits,Pt=Fe.distr==2?Nt.map(Xn=>ii[Xn]):Nt,St=Fe.distr==2?ii[Nt[1]]-ii[Nt[0]]:Ee,it=M.ticks,Ye=M.border,Kt=it.show?it.size:0,ln=bn(Kt*Dt),Cn=bn((M.alignTo==2?M._size-Kt-M.gap:M.gap)*Dt),Gt=M._rotate*-Dl/180,cn=d(M._pos*Dt),si=(ln+Cn)*_e,Wn=cn+si;j=D==0?Wn:0,V=D==1?Wn:0;let vi=M.font[0],Ri=M.align==1?Qr:M.align==2?Au:Gt>0?Qr:Gt<0?Au:D==0?"center":P==3?Au:Qr,Yi=Gt||D==1?"middle":P==2?"top":Qp;De(vi,he,Ri,Yi);let ri=M.font[1]*M.lineGap,bi=Nt.map(Xn=>d(a(Xn,Fe,ze,ct))),Ci=M._values;for(let Xn=0;Xn<Ci.length;Xn++){let oi=Ci[Xn];if(oi!=null){D==0?V=bi[Xn]:j=bi[Xn],oi=""+oi;let fr=oi.indexOf(`
`)==-1?[oi]:oi.split(/\n/gm);for(let $n=0;$n<fr.length;$n++){let tp=fr[$n];Gt?(f.save(),f.translate(V,j+$n*ri),f.rotate(Gt),f.fillText(tp,0,0),f.restore()):f.fillText(tp,V,j+$n*ri)}}}it.show&&dn(bi,it.filter(i,Pt,y,Oe,St),D,P,cn,ln,$t(it.width*Dt,3),it.stroke(i,y),it.dash,it.cap);let Zi=M.grid;Zi.show&&dn(bi,Zi.filter(i,Pt,y,Oe,St),D,D==0?2:1,D==0?b:I,D==0?de:Y,$t(Zi.width*Dt,3),Zi.stroke(i,y),Zi.dash,Zi.cap),Ye.show&&dn([cn],[1],D==0?1:0,D==0?1:2,D==1?b:I,D==1?de:Y,$t(Ye.width*Dt,3),Ye.stroke(i,y),Ye.dash,Ye.cap)}Rn("drawAxes")}function gt(y){x.forEach((M,P)=>{P>0&&(M._paths=null,y&&(s==1?(M.min=null,M.max=null):M.facets.forEach(D=>{D.min=null,D.max=null})))})}let an=!1,Vn=!1,zt=[];function pn(){Vn=!1;for(let y=0;y<zt.length;y++)Rn(...zt[y]);zt.length=0}function Fn(){an||(ux(Fd),an=!0)}function rl(y,M=!1){an=!0,Vn=M,y(i),Fd(),M&&zt.length>0&&queueMicrotask(pn)}i.batch=rl;function Fd(){if(ce&&(xt(),ce=!1),we&&(Re(),we=!1),Me){if(jt(m,Qr,Ke),jt(m,"top",dt),jt(m,ca,F),jt(m,ha,ge),jt(g,Qr,Ke),jt(g,"top",dt),jt(g,ca,F),jt(g,ha,ge),jt(u,ca,ut),jt(u,ha,ft),h.width=bn(ut*Dt),h.height=bn(ft*Dt),A.forEach(({_el:y,_show:M,_size:P,_pos:D,side:V})=>{if(y!=null)if(M){let j=V===3||V===0?P:0,he=V%2==1;jt(y,he?"left":"top",D-j),jt(y,he?"width":"height",P),jt(y,he?"top":"left",he?dt:Ke),jt(y,he?"height":"width",he?ge:F),Ou(y,vr)}else li(y,vr)}),Br=Ps=kr=H=ee=Z=K=Ce=E=null,Le=1,Yo(!0),Ke!=Ae||dt!=Wt||F!=Xe||ge!=Je){gt(!1);let y=F/Xe,M=ge/Je;if(me&&!ie&&le.left>=0){le.left*=y,le.top*=M,Gr&&ji(Gr,bn(le.left),0,F,ge),Hr&&ji(Hr,0,bn(le.top),F,ge);for(let P=0;P<mt.length;P++){let D=mt[P];D!=null&&(qt[P]*=y,Hn[P]*=M,ji(D,wi(qt[P]),wi(Hn[P]),F,ge))}}if(Zt.show&&!oe&&Zt.left>=0&&Zt.width>0){Zt.left*=y,Zt.width*=y,Zt.top*=M,Zt.height*=M;for(let P in nu)jt(Xr,P,Zt[P])}Ae=Ke,Wt=dt,Xe=F,Je=ge}Rn("setSize"),Me=!1}ut>0&&ft>0&&(f.clearRect(0,0,h.width,h.height),Rn("drawClear"),w.forEach(y=>y()),Rn("draw")),Zt.show&&oe&&(ol(Zt),oe=!1),me&&ie&&(ur(null,!0,!1),ie=!1),ne.show&&ne.live&&ye&&(eu(),ye=!1),l||(l=!0,i.status=1,Rn("ready")),Is=!1,an=!1}i.redraw=(y,M)=>{we=M||!1,y!==!1?Ns(T,R.min,R.max):Fn()};function Jh(y,M){let P=S[y];if(P.from==null){if(on==0){let D=P.range(i,M.min,M.max,y);M.min=D[0],M.max=D[1]}if(M.min>M.max){let D=M.min;M.min=M.max,M.max=D}if(on>1&&M.min!=null&&M.max!=null&&M.max-M.min<1e-16)return;y==T&&P.distr==2&&on>0&&(M.min=Li(M.min,e[0]),M.max=Li(M.max,e[0]),M.min==M.max&&M.max++),z[y]=M,ce=!0,Fn()}}i.setScale=Jh;let jh,Qh,Gr,Hr,Bd,kd,Vr,Wr,zd,Gd,Yt,en,Ls=!1,Un=le.drag,Tn=Un.x,An=Un.y;me&&(le.x&&(jh=Mi(Uy,g)),le.y&&(Qh=Mi(Oy,g)),R.ori==0?(Gr=jh,Hr=Qh):(Gr=Qh,Hr=jh),Yt=le.left,en=le.top);let Zt=i.select=yn({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),Xr=Zt.show?Mi(Dy,Zt.over?g:m):null;function ol(y,M){if(Zt.show){for(let P in y)Zt[P]=y[P],P in nu&&jt(Xr,P,y[P]);M!==!1&&Rn("setSelect")}}i.setSelect=ol;function I_(y){if(x[y].show)Q&&Ou(Qe[y],vr);else if(Q&&li(Qe[y],vr),me){let P=Pe?mt[0]:mt[y];P!=null&&ji(P,-10,-10,F,ge)}}function Ns(y,M,P){Jh(y,{min:M,max:P})}function $i(y,M,P,D){M.focus!=null&&U_(y),M.show!=null&&x.forEach((V,j)=>{j>0&&(y==j||y==null)&&(V.show=M.show,I_(j),s==2?(Ns(V.facets[0].scale,null,null),Ns(V.facets[1].scale,null,null)):Ns(V.scale,null,null),Fn())}),P!==!1&&Rn("setSeries",y,M),D&&Zo("setSeries",i,y,M)}i.setSeries=$i;function P_(y,M){yn(C[y],M)}function L_(y,M){y.fill=Tt(y.fill||null),y.dir=Lt(y.dir,-1),M=M??C.length,C.splice(M,0,y)}function N_(y){y==null?C.length=0:C.splice(y,1)}i.addBand=L_,i.setBand=P_,i.delBand=N_;function D_(y,M){x[y].alpha=M,me&&mt[y]!=null&&(mt[y].style.opacity=M),Q&&Qe[y]&&(Qe[y].style.opacity=M)}let us,Ds,hr,$r={focus:!0};function U_(y){if(y!=hr){let M=y==null,P=Ge.alpha!=1;x.forEach((D,V)=>{if(s==1||V>0){let j=M||V==0||V==y;D._focus=M?null:j,P&&D_(V,j?1:Ge.alpha)}}),hr=y,P&&Fn()}}Q&&rt&&et(im,be,y=>{le._lock||(st(y),hr!=null&&$i(null,$r,!0,mn.setSeries))});function qi(y,M,P){let D=S[M];P&&(y=y/Dt-(D.ori==1?dt:Ke));let V=F;D.ori==1&&(V=ge,y=V-y),D.dir==-1&&(y=V-y);let j=D._min,he=D._max,_e=y/V,Ee=j+(he-j)*_e,Oe=D.distr;return Oe==3?no(10,Ee):Oe==4?Qy(Ee,D.asinh):Oe==100?D.bwd(Ee):Ee}function O_(y,M){let P=qi(y,T,M);return Li(P,e[0],hn,un)}i.valToIdx=y=>Li(y,e[0]),i.posToIdx=O_,i.posToVal=qi,i.valToPos=(y,M,P)=>S[M].ori==0?r(y,S[M],P?Y:F,P?I:0):o(y,S[M],P?de:ge,P?b:0),i.setCursor=(y,M,P)=>{Yt=y.left,en=y.top,ur(null,M,P)};function Hd(y,M){jt(Xr,Qr,Zt.left=y),jt(Xr,ca,Zt.width=M)}function Vd(y,M){jt(Xr,"top",Zt.top=y),jt(Xr,ha,Zt.height=M)}let $o=R.ori==0?Hd:Vd,qo=R.ori==1?Hd:Vd;function F_(){if(Q&&ne.live)for(let y=s==2?1:0;y<x.length;y++){if(y==0&&tt)continue;let M=ne.values[y],P=0;for(let D in M)Ne[y][P++].firstChild.nodeValue=M[D]}}function eu(y,M){if(y!=null&&(y.idxs?y.idxs.forEach((P,D)=>{W[D]=P}):ix(y.idx)||W.fill(y.idx),ne.idx=W[0]),Q&&ne.live){for(let P=0;P<x.length;P++)(P>0||s==1&&!tt)&&B_(P,W[P]);F_()}ye=!1,M!==!1&&Rn("setLegend")}i.setLegend=eu;function B_(y,M){let P=x[y],D=y==0&&G==2?ii:e[y],V;tt?V=P.values(i,y,M)??fe:(V=P.value(i,M==null?null:D[M],y,M),V=V==null?fe:{_:V}),ne.values[y]=V}function ur(y,M,P){zd=Yt,Gd=en,[Yt,en]=le.move(i,Yt,en),le.left=Yt,le.top=en,me&&(Gr&&ji(Gr,bn(Yt),0,F,ge),Hr&&ji(Hr,0,bn(en),F,ge));let D,V=hn>un;us=Xt,Ds=null;let j=R.ori==0?F:ge,he=R.ori==1?F:ge;if(Yt<0||on==0||V){D=le.idx=null;for(let _e=0;_e<x.length;_e++){let Ee=mt[_e];Ee!=null&&ji(Ee,-10,-10,F,ge)}rt&&$i(null,$r,!0,y==null&&mn.setSeries),ne.live&&(W.fill(D),ye=!0)}else{let _e,Ee,Oe;s==1&&(_e=R.ori==0?Yt:en,Ee=qi(_e,T),D=le.idx=Li(Ee,e[0],hn,un),Oe=B(e[0][D],R,j,0));let Fe=-10,ze=-10,ct=0,Nt=0,Pt=!0,St="",it="";for(let Ye=s==2?1:0;Ye<x.length;Ye++){let Kt=x[Ye],ln=W[Ye],Cn=ln==null?null:s==1?e[Ye][ln]:e[Ye][1][ln],Gt=le.dataIdx(i,Ye,D,Ee),cn=Gt==null?null:s==1?e[Ye][Gt]:e[Ye][1][Gt];if(ye=ye||cn!=Cn||Gt!=ln,W[Ye]=Gt,Ye>0&&Kt.show){let si=Gt==null?-10:Gt==D?Oe:B(s==1?e[0][Gt]:e[Ye][0][Gt],R,j,0),Wn=cn==null?-10:L(cn,s==1?S[Kt.scale]:S[Kt.facets[1].scale],he,0);if(rt&&cn!=null){let vi=R.ori==1?Yt:en,Ri=Sn(Ge.dist(i,Ye,Gt,Wn,vi));if(Ri<us){let Yi=Ge.bias;if(Yi!=0){let ri=qi(vi,Kt.scale),bi=cn>=0?1:-1,Ci=ri>=0?1:-1;Ci==bi&&(Ci==1?Yi==1?cn>=ri:cn<=ri:Yi==1?cn<=ri:cn>=ri)&&(us=Ri,Ds=Ye)}else us=Ri,Ds=Ye}}if(ye||Pe){let vi,Ri;R.ori==0?(vi=si,Ri=Wn):(vi=Wn,Ri=si);let Yi,ri,bi,Ci,Zi,Xn,oi=!0,fr=ue.bbox;if(fr!=null){oi=!1;let $n=fr(i,Ye);bi=$n.left,Ci=$n.top,Yi=$n.width,ri=$n.height}else bi=vi,Ci=Ri,Yi=ri=ue.size(i,Ye);if(Xn=ue.fill(i,Ye),Zi=ue.stroke(i,Ye),Pe)Ye==Ds&&us<=Ge.prox&&(Fe=bi,ze=Ci,ct=Yi,Nt=ri,Pt=oi,St=Xn,it=Zi);else{let $n=mt[Ye];$n!=null&&(qt[Ye]=bi,Hn[Ye]=Ci,hm($n,Yi,ri,oi),lm($n,Xn,Zi),ji($n,wi(bi),wi(Ci),F,ge))}}}}if(Pe){let Ye=Ge.prox,Kt=hr==null?us<=Ye:us>Ye||Ds!=hr;if(ye||Kt){let ln=mt[0];ln!=null&&(qt[0]=Fe,Hn[0]=ze,hm(ln,ct,Nt,Pt),lm(ln,St,it),ji(ln,wi(Fe),wi(ze),F,ge))}}}if(Zt.show&&Ls)if(y!=null){let[_e,Ee]=mn.scales,[Oe,Fe]=mn.match,[ze,ct]=y.cursor.sync.scales,Nt=y.cursor.drag;if(Tn=Nt._x,An=Nt._y,Tn||An){let{left:Pt,top:St,width:it,height:Ye}=y.select,Kt=y.scales[ze].ori,ln=y.posToVal,Cn,Gt,cn,si,Wn,vi=_e!=null&&Oe(_e,ze),Ri=Ee!=null&&Fe(Ee,ct);vi&&Tn?(Kt==0?(Cn=Pt,Gt=it):(Cn=St,Gt=Ye),cn=S[_e],si=B(ln(Cn,ze),cn,j,0),Wn=B(ln(Cn+Gt,ze),cn,j,0),$o(Ni(si,Wn),Sn(Wn-si))):$o(0,j),Ri&&An?(Kt==1?(Cn=Pt,Gt=it):(Cn=St,Gt=Ye),cn=S[Ee],si=L(ln(Cn,ct),cn,he,0),Wn=L(ln(Cn+Gt,ct),cn,he,0),qo(Ni(si,Wn),Sn(Wn-si))):qo(0,he)}else iu()}else{let _e=Sn(zd-Bd),Ee=Sn(Gd-kd);if(R.ori==1){let ct=_e;_e=Ee,Ee=ct}Tn=Un.x&&_e>=Un.dist,An=Un.y&&Ee>=Un.dist;let Oe=Un.uni;Oe!=null?Tn&&An&&(Tn=_e>=Oe,An=Ee>=Oe,!Tn&&!An&&(Ee>_e?An=!0:Tn=!0)):Un.x&&Un.y&&(Tn||An)&&(Tn=An=!0);let Fe,ze;Tn&&(R.ori==0?(Fe=Vr,ze=Yt):(Fe=Wr,ze=en),$o(Ni(Fe,ze),Sn(ze-Fe)),An||qo(0,he)),An&&(R.ori==1?(Fe=Vr,ze=Yt):(Fe=Wr,ze=en),qo(Ni(Fe,ze),Sn(ze-Fe)),Tn||$o(0,j)),!Tn&&!An&&($o(0,0),qo(0,0))}if(Un._x=Tn,Un._y=An,y==null){if(P){if(ep!=null){let[_e,Ee]=mn.scales;mn.values[0]=_e!=null?qi(R.ori==0?Yt:en,_e):null,mn.values[1]=Ee!=null?qi(R.ori==1?Yt:en,Ee):null}Zo(Ru,i,Yt,en,F,ge,D)}if(rt){let _e=P&&mn.setSeries,Ee=Ge.prox;hr==null?us<=Ee&&$i(Ds,$r,!0,_e):us>Ee?$i(null,$r,!0,_e):Ds!=hr&&$i(Ds,$r,!0,_e)}}ye&&(ne.idx=D,eu()),M!==!1&&Rn("setCursor")}let Us=null;Object.defineProperty(i,"rect",{get(){return Us==null&&Yo(!1),Us}});function Yo(y=!1){y?Us=null:(Us=g.getBoundingClientRect(),Rn("syncRect",Us))}function Wd(y,M,P,D,V,j,he){le._lock||Ls&&y!=null&&y.movementX==0&&y.movementY==0||(tu(y,M,P,D,V,j,he,!1,y!=null),y!=null?ur(null,!0,!0):ur(M,!0,!1))}function tu(y,M,P,D,V,j,he,_e,Ee){if(Us==null&&Yo(!1),st(y),y!=null)P=y.clientX-Us.left,D=y.clientY-Us.top;else{if(P<0||D<0){Yt=-10,en=-10;return}let[Oe,Fe]=mn.scales,ze=M.cursor.sync,[ct,Nt]=ze.values,[Pt,St]=ze.scales,[it,Ye]=mn.match,Kt=M.axes[0].side%2==1,ln=R.ori==0?F:ge,Cn=R.ori==1?F:ge,Gt=Kt?j:V,cn=Kt?V:j,si=Kt?D:P,Wn=Kt?P:D;if(Pt!=null?P=it(Oe,Pt)?a(ct,S[Oe],ln,0):-10:P=ln*(si/Gt),St!=null?D=Ye(Fe,St)?a(Nt,S[Fe],Cn,0):-10:D=Cn*(Wn/cn),R.ori==1){let vi=P;P=D,D=vi}}Ee&&(M==null||M.cursor.event.type==Ru)&&((P<=1||P>=F-1)&&(P=yr(P,F)),(D<=1||D>=ge-1)&&(D=yr(D,ge))),_e?(Bd=P,kd=D,[Vr,Wr]=le.move(i,P,D)):(Yt=P,en=D)}let nu={width:0,height:0,left:0,top:0};function iu(){ol(nu,!1)}let Xd,$d,qd,Yd;function Zd(y,M,P,D,V,j,he){Ls=!0,Tn=An=Un._x=Un._y=!1,tu(y,M,P,D,V,j,he,!0,!1),y!=null&&(et(Cu,Du,Kd,!1),Zo(tm,i,Vr,Wr,F,ge,null));let{left:_e,top:Ee,width:Oe,height:Fe}=Zt;Xd=_e,$d=Ee,qd=Oe,Yd=Fe}function Kd(y,M,P,D,V,j,he){Ls=Un._x=Un._y=!1,tu(y,M,P,D,V,j,he,!1,!0);let{left:_e,top:Ee,width:Oe,height:Fe}=Zt,ze=Oe>0||Fe>0,ct=Xd!=_e||$d!=Ee||qd!=Oe||Yd!=Fe;if(ze&&ct&&ol(Zt),Un.setScale&&ze&&ct){let Nt=_e,Pt=Oe,St=Ee,it=Fe;if(R.ori==1&&(Nt=Ee,Pt=Fe,St=_e,it=Oe),Tn&&Ns(T,qi(Nt,T),qi(Nt+Pt,T)),An)for(let Ye in S){let Kt=S[Ye];Ye!=T&&Kt.from==null&&Kt.min!=Xt&&Ns(Ye,qi(St+it,Ye),qi(St,Ye))}iu()}else le.lock&&(le._lock=!le._lock,ur(M,!0,y!=null));y!=null&&(Ct(Cu,Du),Zo(Cu,i,Yt,en,F,ge,null))}function k_(y,M,P,D,V,j,he){if(le._lock)return;st(y);let _e=Ls;if(Ls){let Ee=!0,Oe=!0,Fe=10,ze,ct;R.ori==0?(ze=Tn,ct=An):(ze=An,ct=Tn),ze&&ct&&(Ee=Yt<=Fe||Yt>=F-Fe,Oe=en<=Fe||en>=ge-Fe),ze&&Ee&&(Yt=Yt<Vr?0:F),ct&&Oe&&(en=en<Wr?0:ge),ur(null,!0,!0),Ls=!1}Yt=-10,en=-10,W.fill(null),ur(null,!0,!0),_e&&(Ls=_e)}function Jd(y,M,P,D,V,j,he){le._lock||(st(y),Xo(),iu(),y!=null&&Zo(sm,i,Yt,en,F,ge,null))}function jd(){A.forEach(xv),k(i.width,i.height,!0)}br(Ul,to,jd);let qr={};qr.mousedown=Zd,qr.mousemove=Wd,qr.mouseup=Kd,qr.dblclick=Jd,qr.setSeries=(y,M,P,D)=>{let V=mn.match[2];P=V(i,M,P),P!=-1&&$i(P,D,!0,!1)},me&&(et(tm,g,Zd),et(Ru,g,Wd),et(nm,g,y=>{st(y),Yo(!1)}),et(im,g,k_),et(sm,g,Jd),Hu.add(i),i.syncRect=Yo);let al=i.hooks=n.hooks||{};function Rn(y,M,P){Vn?zt.push([y,M,P]):y in al&&al[y].forEach(D=>{D.call(null,i,M,P)})}(n.plugins||[]).forEach(y=>{for(let M in y.hooks)al[M]=(al[M]||[]).concat(y.hooks[M])});let Qd=(y,M,P)=>P,mn=yn({key:null,setSeries:!1,filters:{pub:mm,sub:mm},scales:[T,x[1]?x[1].scale:null],match:[gm,gm,Qd],values:[null,null]},le.sync);mn.match.length==2&&mn.match.push(Qd),le.sync=mn;let ep=mn.key,su=fg(ep);function Zo(y,M,P,D,V,j,he){mn.filters.pub(y,M,P,D,V,j,he)&&su.pub(y,M,P,D,V,j,he)}su.sub(i);function z_(y,M,P,D,V,j,he){mn.filters.sub(y,M,P,D,V,j,he)&&qr[y](null,M,P,D,V,j,he)}i.pub=z_;function G_(){su.unsub(i),Hu.delete(i),Vt.clear(),Fu(Ul,to,jd),c.remove(),be?.remove(),Rn("destroy")}i.destroy=G_;function ru(){Rn("init",n,e),Wo(e||n.data,!1),z[T]?Jh(T,z[T]):Xo(),oe=Zt.show&&(Zt.width>0||Zt.height>0),ie=ye=!0,k(n.width,n.height)}return x.forEach(Fr),A.forEach(as),t?t instanceof HTMLElement?(t.appendChild(c),ru()):t(i,ru):ru(),i}Pn.assign=yn;Pn.fmtNum=Zu;Pn.rangeNum=Ol;Pn.rangeLog=kl;Pn.rangeAsinh=qu;Pn.orient=Mr;Pn.pxRatio=Dt;Pn.join=hx;Pn.fmtDate=Ju,Pn.tzDate=bx;Pn.sync=fg;{Pn.addGap=iv,Pn.clipGaps=Hl;let n=Pn.paths={points:yg};n.linear=vg,n.stepped=ov,n.bars=av,n.spline=cv}var wr=class{constructor(e,t){this.keep=t;this.ys=Array.from({length:e},()=>[])}keep;t=[];ys;push(e,...t){if(this.t.push(e),t.forEach((i,s)=>this.ys[s].push(i!=null&&Number.isFinite(i)?i:null)),this.t.length>this.keep){this.t.shift();for(let i of this.ys)i.shift()}}},co=class{constructor(e,t,i,s=120,r=28){this.s=t;let o=document.createElement("span");o.className="spark",e.appendChild(o),this.plot=new Pn({width:s,height:r,cursor:{show:!1},legend:{show:!1},select:{show:!1},axes:[{show:!1},{show:!1}],scales:{x:{time:!1},y:{range:(a,l,c)=>[Math.min(0,l),c>0?c*1.1:1]}},series:[{},{stroke:i,width:1.5,fill:i+"33",points:{show:!1}}]},[[],[]],o),o.appendChild(this.label)}s;plot;label=document.createElement("span");update(e){this.plot.setData([this.s.t,this.s.ys[0]]),this.label.textContent=e}destroy(){this.plot.destroy()}},$l=class{constructor(e,t,i,s,r){this.s=t;this.plot=new Pn({width:s,height:r,scales:{x:{time:!0}},axes:[{stroke:"#8a96a3",grid:{stroke:"#1f2a35"}},{stroke:"#8a96a3",grid:{stroke:"#1f2a35"},scale:i[0].scale},...i.some(o=>o.scale==="r")?[{side:1,scale:"r",stroke:"#8a96a3",grid:{show:!1}}]:[]],series:[{},...i.map(o=>({label:o.label,stroke:o.colour,width:1.5,scale:o.scale,points:{show:!1}}))]},[[],...i.map(()=>[])],e)}s;plot;update(){this.plot.setData([this.s.t,...this.s.ys])}destroy(){this.plot.destroy()}};var rr={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},or={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},jg=0,Lf=1,Qg=2;var Wa=1,e0=2,Uo=3,ar=0,Kn=1,is=2,Pr=0,Oo=1,Nf=2,Df=3,Uf=4,t0=5;var Lr=100,n0=101,i0=102,s0=103,r0=104,o0=200,a0=201,l0=202,c0=203,Of=204,Ff=205,h0=206,u0=207,f0=208,d0=209,p0=210,m0=211,g0=212,_0=213,y0=214,xc=0,vc=1,bc=2,Eo=3,Sc=4,Mc=5,wc=6,Ec=7,Bf=0,x0=1,v0=2,ss=0,kf=1,zf=2,Gf=3,Hf=4,Vf=5,Wf=6,Xf=7;var $f=300,Nr=301,Fo=302,eh=303,th=304,Tc=1e3,es=1001,Ac=1002,Dn=1003,b0=1004;var Xa=1005;var Zn=1006,nh=1007;var Ts=1008;var xi=1009,qf=1010,Yf=1011,Bo=1012,ih=1013,Bi=1014,ki=1015,zi=1016,sh=1017,rh=1018,Dr=1020,Zf=35902,Kf=35899,Jf=1021,jf=1022,Gi=1023,Ms=1026,As=1027,Qf=1028,oh=1029,lr=1030,ah=1031;var lh=1033,$a=33776,qa=33777,Ya=33778,Za=33779,ch=35840,hh=35841,uh=35842,fh=35843,dh=36196,ph=37492,mh=37496,gh=37488,_h=37489,Ka=37490,yh=37491,xh=37808,vh=37809,bh=37810,Sh=37811,Mh=37812,wh=37813,Eh=37814,Th=37815,Ah=37816,Rh=37817,Ch=37818,Ih=37819,Ph=37820,Lh=37821,Nh=36492,Dh=36494,Uh=36495,Oh=36283,Fh=36284,Ja=36285,Bh=36286;var Ma=2300,Rc=2301,_c=2302,Ef=2303,Tf=2400,Af=2401,Rf=2402;var S0=3200;var ed=0,M0=1,Rs="",di="srgb",wa="srgb-linear",Ea="linear",Ft="srgb";var yc=7680;var w0=519,E0=512,T0=513,A0=514,td=515,R0=516,C0=517,nd=518,id=519,I0=35044;var sd="300 es",Ti=2e3,Ta=2001;function vv(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function bv(n){return ArrayBuffer.isView(n)&&!(n instanceof DataView)}function Aa(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function P0(){let n=Aa("canvas");return n.style.display="block",n}var wg={},To=null;function rd(...n){let e="THREE."+n.shift();To?To("log",e,...n):console.log(e,...n)}function L0(n){let e=n[0];if(typeof e=="string"&&e.startsWith("TSL:")){let t=n[1];t&&t.isStackTrace?n[0]+=" "+t.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function je(...n){n=L0(n);let e="THREE."+n.shift();if(To)To("warn",e,...n);else{let t=n[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...n)}}function at(...n){n=L0(n);let e="THREE."+n.shift();if(To)To("error",e,...n);else{let t=n[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...n)}}function va(...n){let e=n.join(" ");e in wg||(wg[e]=!0,je(...n))}function N0(n,e,t){return new Promise(function(i,s){function r(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:s();break;case n.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:i()}}setTimeout(r,t)})}var D0={[xc]:xc,[bc]:wc,[Sc]:Sc,[Eo]:Mc,[vc]:vc,[wc]:bc,[Ec]:Ec,[Mc]:Eo},Fi=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let i=this._listeners;i[e]===void 0&&(i[e]=[]),i[e].indexOf(t)===-1&&i[e].push(t)}hasEventListener(e,t){let i=this._listeners;return i===void 0?!1:i[e]!==void 0&&i[e].indexOf(t)!==-1}removeEventListener(e,t){let i=this._listeners;if(i===void 0)return;let s=i[e];if(s!==void 0){let r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){let t=this._listeners;if(t===void 0)return;let i=t[e.type];if(i!==void 0){e.target=this;let s=i.slice(0);for(let r=0,o=s.length;r<o;r++)s[r].call(this,e);e.target=null}}},kn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Eg=1234567,ba=Math.PI/180,Ao=180/Math.PI;function ko(){let n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(kn[n&255]+kn[n>>8&255]+kn[n>>16&255]+kn[n>>24&255]+"-"+kn[e&255]+kn[e>>8&255]+"-"+kn[e>>16&15|64]+kn[e>>24&255]+"-"+kn[t&63|128]+kn[t>>8&255]+"-"+kn[t>>16&255]+kn[t>>24&255]+kn[i&255]+kn[i>>8&255]+kn[i>>16&255]+kn[i>>24&255]).toLowerCase()}function bt(n,e,t){return Math.max(e,Math.min(t,n))}function od(n,e){return(n%e+e)%e}function Sv(n,e,t,i,s){return i+(n-e)*(s-i)/(t-e)}function Mv(n,e,t){return n!==e?(t-n)/(e-n):0}function Sa(n,e,t){return(1-t)*n+t*e}function wv(n,e,t,i){return Sa(n,e,1-Math.exp(-t*i))}function Ev(n,e=1){return e-Math.abs(od(n,e*2)-e)}function Tv(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*(3-2*n))}function Av(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*n*(n*(n*6-15)+10))}function Rv(n,e){return n+Math.floor(Math.random()*(e-n+1))}function Cv(n,e){return n+Math.random()*(e-n)}function Iv(n){return n*(.5-Math.random())}function Pv(n){n!==void 0&&(Eg=n);let e=Eg+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function Lv(n){return n*ba}function Nv(n){return n*Ao}function Dv(n){return n>0&&Number.isInteger(n)&&2**Math.round(Math.log2(n))===n}function Uv(n){return Math.pow(2,Math.ceil(Math.log(n)/Math.LN2))}function ad(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function Ov(n,e,t,i,s){let r=Math.cos,o=Math.sin,a=r(t/2),l=o(t/2),c=r((e+i)/2),h=o((e+i)/2),f=r((e-i)/2),u=o((e-i)/2),m=r((i-e)/2),g=o((i-e)/2);switch(s){case"XYX":n.set(a*h,l*f,l*u,a*c);break;case"YZY":n.set(l*u,a*h,l*f,a*c);break;case"ZXZ":n.set(l*f,l*u,a*h,a*c);break;case"XZX":n.set(a*h,l*g,l*m,a*c);break;case"YXY":n.set(l*m,a*h,l*g,a*c);break;case"ZYZ":n.set(l*g,l*m,a*h,a*c);break;default:je("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+s)}}function ld(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function U0(n,e){if(e.constructor===Float32Array)return n;let t=ld(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/t,-1)}function O0(n,e){if(e.constructor===Float32Array)return n;let t=ld(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*t)}var cd={DEG2RAD:ba,RAD2DEG:Ao,generateUUID:ko,clamp:bt,euclideanModulo:od,mapLinear:Sv,inverseLerp:Mv,lerp:Sa,damp:wv,pingpong:Ev,smoothstep:Tv,smootherstep:Av,randInt:Rv,randFloat:Cv,randFloatSpread:Iv,seededRandom:Pv,degToRad:Lv,radToDeg:Nv,isPowerOfTwo:Dv,ceilPowerOfTwo:Uv,floorPowerOfTwo:ad,setQuaternionFromProperEuler:Ov,normalize:O0,denormalize:U0},pd=class pd{constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,i=this.y,s=e.elements;return this.x=s[0]*t+s[3]*i+s[6],this.y=s[1]*t+s[4]*i+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=bt(this.x,e.x,t.x),this.y=bt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=bt(this.x,e,t),this.y=bt(this.y,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(bt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(bt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y;return t*t+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let i=Math.cos(t),s=Math.sin(t),r=this.x-e.x,o=this.y-e.y;return this.x=r*i-o*s+e.x,this.y=r*s+o*i+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};pd.prototype.isVector2=!0;var pt=pd,gi=class{constructor(e=0,t=0,i=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=i,this._w=s}static slerpFlat(e,t,i,s,r,o,a){let l=i[s+0],c=i[s+1],h=i[s+2],f=i[s+3],u=r[o+0],m=r[o+1],g=r[o+2],v=r[o+3];if(f!==v||l!==u||c!==m||h!==g){let d=l*u+c*m+h*g+f*v;d<0&&(u=-u,m=-m,g=-g,v=-v,d=-d);let p=1-a;if(d<.9995){let x=Math.acos(d),A=Math.sin(x);p=Math.sin(p*x)/A,a=Math.sin(a*x)/A,l=l*p+u*a,c=c*p+m*a,h=h*p+g*a,f=f*p+v*a}else{l=l*p+u*a,c=c*p+m*a,h=h*p+g*a,f=f*p+v*a;let x=1/Math.sqrt(l*l+c*c+h*h+f*f);l*=x,c*=x,h*=x,f*=x}}e[t]=l,e[t+1]=c,e[t+2]=h,e[t+3]=f}static multiplyQuaternionsFlat(e,t,i,s,r,o){let a=i[s],l=i[s+1],c=i[s+2],h=i[s+3],f=r[o],u=r[o+1],m=r[o+2],g=r[o+3];return e[t]=a*g+h*f+l*m-c*u,e[t+1]=l*g+h*u+c*f-a*m,e[t+2]=c*g+h*m+a*u-l*f,e[t+3]=h*g-a*f-l*u-c*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,i,s){return this._x=e,this._y=t,this._z=i,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let i=e._x,s=e._y,r=e._z,o=e._order,a=Math.cos,l=Math.sin,c=a(i/2),h=a(s/2),f=a(r/2),u=l(i/2),m=l(s/2),g=l(r/2);switch(o){case"XYZ":this._x=u*h*f+c*m*g,this._y=c*m*f-u*h*g,this._z=c*h*g+u*m*f,this._w=c*h*f-u*m*g;break;case"YXZ":this._x=u*h*f+c*m*g,this._y=c*m*f-u*h*g,this._z=c*h*g-u*m*f,this._w=c*h*f+u*m*g;break;case"ZXY":this._x=u*h*f-c*m*g,this._y=c*m*f+u*h*g,this._z=c*h*g+u*m*f,this._w=c*h*f-u*m*g;break;case"ZYX":this._x=u*h*f-c*m*g,this._y=c*m*f+u*h*g,this._z=c*h*g-u*m*f,this._w=c*h*f+u*m*g;break;case"YZX":this._x=u*h*f+c*m*g,this._y=c*m*f+u*h*g,this._z=c*h*g-u*m*f,this._w=c*h*f-u*m*g;break;case"XZY":this._x=u*h*f-c*m*g,this._y=c*m*f-u*h*g,this._z=c*h*g+u*m*f,this._w=c*h*f+u*m*g;break;default:je("Quaternion: .setFromEuler() encountered an unknown order: "+o)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let i=t/2,s=Math.sin(i);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,i=t[0],s=t[4],r=t[8],o=t[1],a=t[5],l=t[9],c=t[2],h=t[6],f=t[10],u=i+a+f;if(u>0){let m=.5/Math.sqrt(u+1);this._w=.25/m,this._x=(h-l)*m,this._y=(r-c)*m,this._z=(o-s)*m}else if(i>a&&i>f){let m=2*Math.sqrt(1+i-a-f);this._w=(h-l)/m,this._x=.25*m,this._y=(s+o)/m,this._z=(r+c)/m}else if(a>f){let m=2*Math.sqrt(1+a-i-f);this._w=(r-c)/m,this._x=(s+o)/m,this._y=.25*m,this._z=(l+h)/m}else{let m=2*Math.sqrt(1+f-i-a);this._w=(o-s)/m,this._x=(r+c)/m,this._y=(l+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let i=e.dot(t)+1;return i<1e-8?(i=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=i):(this._x=0,this._y=-e.z,this._z=e.y,this._w=i)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=i),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(bt(this.dot(e),-1,1)))}rotateTowards(e,t){let i=this.angleTo(e);if(i===0)return this;let s=Math.min(1,t/i);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=t._x,l=t._y,c=t._z,h=t._w;return this._x=i*h+o*a+s*c-r*l,this._y=s*h+o*l+r*a-i*c,this._z=r*h+o*c+i*l-s*a,this._w=o*h-i*a-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=this.dot(e);a<0&&(i=-i,s=-s,r=-r,o=-o,a=-a);let l=1-t;if(a<.9995){let c=Math.acos(a),h=Math.sin(c);l=Math.sin(l*c)/h,t=Math.sin(t*c)/h,this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+o*t,this._onChangeCallback()}else this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+o*t,this.normalize();return this}slerpQuaternions(e,t,i){return this.copy(e).slerp(t,i)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),i=Math.random(),s=Math.sqrt(1-i),r=Math.sqrt(i);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},md=class md{constructor(e=0,t=0,i=0){this.x=e,this.y=t,this.z=i}set(e,t,i){return i===void 0&&(i=this.z),this.x=e,this.y=t,this.z=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Tg.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Tg.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*i+r[6]*s,this.y=r[1]*t+r[4]*i+r[7]*s,this.z=r[2]*t+r[5]*i+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=e.elements,o=1/(r[3]*t+r[7]*i+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*i+r[8]*s+r[12])*o,this.y=(r[1]*t+r[5]*i+r[9]*s+r[13])*o,this.z=(r[2]*t+r[6]*i+r[10]*s+r[14])*o,this}applyQuaternion(e){let t=this.x,i=this.y,s=this.z,r=e.x,o=e.y,a=e.z,l=e.w,c=2*(o*s-a*i),h=2*(a*t-r*s),f=2*(r*i-o*t);return this.x=t+l*c+o*f-a*h,this.y=i+l*h+a*c-r*f,this.z=s+l*f+r*h-o*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*i+r[8]*s,this.y=r[1]*t+r[5]*i+r[9]*s,this.z=r[2]*t+r[6]*i+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=bt(this.x,e.x,t.x),this.y=bt(this.y,e.y,t.y),this.z=bt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=bt(this.x,e,t),this.y=bt(this.y,e,t),this.z=bt(this.z,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(bt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let i=e.x,s=e.y,r=e.z,o=t.x,a=t.y,l=t.z;return this.x=s*l-r*a,this.y=r*o-i*l,this.z=i*a-s*o,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let i=e.dot(this)/t;return this.copy(e).multiplyScalar(i)}projectOnPlane(e){return rf.copy(this).projectOnVector(e),this.sub(rf)}reflect(e){return this.sub(rf.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(bt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y,s=this.z-e.z;return t*t+i*i+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,i){let s=Math.sin(t)*e;return this.x=s*Math.sin(i),this.y=Math.cos(t)*e,this.z=s*Math.cos(i),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,i){return this.x=e*Math.sin(t),this.y=i,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),i=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=i,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,i=Math.sqrt(1-t*t);return this.x=i*Math.cos(e),this.y=t,this.z=i*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};md.prototype.isVector3=!0;var J=md,rf=new J,Tg=new gi,gd=class gd{constructor(e,t,i,s,r,o,a,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,l,c)}set(e,t,i,s,r,o,a,l,c){let h=this.elements;return h[0]=e,h[1]=s,h[2]=a,h[3]=t,h[4]=r,h[5]=l,h[6]=i,h[7]=o,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],this}extractBasis(e,t,i){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[3],l=i[6],c=i[1],h=i[4],f=i[7],u=i[2],m=i[5],g=i[8],v=s[0],d=s[3],p=s[6],x=s[1],A=s[4],S=s[7],C=s[2],T=s[5],_=s[8];return r[0]=o*v+a*x+l*C,r[3]=o*d+a*A+l*T,r[6]=o*p+a*S+l*_,r[1]=c*v+h*x+f*C,r[4]=c*d+h*A+f*T,r[7]=c*p+h*S+f*_,r[2]=u*v+m*x+g*C,r[5]=u*d+m*A+g*T,r[8]=u*p+m*S+g*_,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8];return t*o*h-t*a*c-i*r*h+i*a*l+s*r*c-s*o*l}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8],f=h*o-a*c,u=a*l-h*r,m=c*r-o*l,g=t*f+i*u+s*m;if(g===0)return this.set(0,0,0,0,0,0,0,0,0);let v=1/g;return e[0]=f*v,e[1]=(s*c-h*i)*v,e[2]=(a*i-s*o)*v,e[3]=u*v,e[4]=(h*t-s*l)*v,e[5]=(s*r-a*t)*v,e[6]=m*v,e[7]=(i*l-c*t)*v,e[8]=(o*t-i*r)*v,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,i,s,r,o,a){let l=Math.cos(r),c=Math.sin(r);return this.set(i*l,i*c,-i*(l*o+c*a)+o+e,-s*c,s*l,-s*(-c*o+l*a)+a+t,0,0,1),this}scale(e,t){return va("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(of.makeScale(e,t)),this}rotate(e){return va("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(of.makeRotation(-e)),this}translate(e,t){return va("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(of.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,i,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<9;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<9;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e}clone(){return new this.constructor().fromArray(this.elements)}};gd.prototype.isMatrix3=!0;var lt=gd,of=new lt,Ag=new lt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Rg=new lt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function Fv(){let n={enabled:!0,workingColorSpace:wa,spaces:{},convert:function(s,r,o){return this.enabled===!1||r===o||!r||!o||(this.spaces[r].transfer===Ft&&(s.r=Ss(s.r),s.g=Ss(s.g),s.b=Ss(s.b)),this.spaces[r].primaries!==this.spaces[o].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[o].fromXYZ)),this.spaces[o].transfer===Ft&&(s.r=wo(s.r),s.g=wo(s.g),s.b=wo(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Rs?Ea:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,o){return s.copy(this.spaces[o].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[wa]:{primaries:e,whitePoint:i,transfer:Ea,toXYZ:Ag,fromXYZ:Rg,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:di},outputColorSpaceConfig:{drawingBufferColorSpace:di}},[di]:{primaries:e,whitePoint:i,transfer:Ft,toXYZ:Ag,fromXYZ:Rg,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:di}}}),n}var At=Fv();function Ss(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function wo(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}var ho,Cc=class{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let i;if(e instanceof HTMLCanvasElement)i=e;else{ho===void 0&&(ho=Aa("canvas")),ho.width=e.width,ho.height=e.height;let s=ho.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),i=ho}return i.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=Aa("canvas");t.width=e.width,t.height=e.height;let i=t.getContext("2d");i.drawImage(e,0,0,e.width,e.height);let s=i.getImageData(0,0,e.width,e.height),r=s.data;for(let o=0;o<r.length;o++)r[o]=Ss(r[o]/255)*255;return i.putImageData(s,0,0),t}else if(e.data){let t=e.data.slice(0);for(let i=0;i<t.length;i++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[i]=Math.floor(Ss(t[i]/255)*255):t[i]=Ss(t[i]);return{data:t,width:e.width,height:e.height}}else return je("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},Bv=0,Ro=class{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:Bv++}),this.uuid=ko(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){let t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let i={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let o=0,a=s.length;o<a;o++)s[o].isDataTexture?r.push(af(s[o].image)):r.push(af(s[o]))}else r=af(s);i.url=r}return t||(e.images[this.uuid]=i),i}};function af(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?Cc.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(je("Texture: Unable to serialize Texture."),{})}var kv=0,lf=new J,Qn=class n extends Fi{constructor(e=n.DEFAULT_IMAGE,t=n.DEFAULT_MAPPING,i=es,s=es,r=Zn,o=Ts,a=Gi,l=xi,c=n.DEFAULT_ANISOTROPY,h=Rs){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:kv++}),this.uuid=ko(),this.name="",this.source=new Ro(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=i,this.wrapT=s,this.magFilter=r,this.minFilter=o,this.anisotropy=c,this.format=a,this.internalFormat=null,this.type=l,this.offset=new pt(0,0),this.repeat=new pt(1,1),this.center=new pt(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new lt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(lf).x}get height(){return this.source.getSize(lf).y}get depth(){return this.source.getSize(lf).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(let t in e){let i=e[t];if(i===void 0){je(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){je(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&i&&s.isVector2&&i.isVector2||s&&i&&s.isVector3&&i.isVector3||s&&i&&s.isMatrix3&&i.isMatrix3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),t||(e.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==$f)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case Tc:e.x=e.x-Math.floor(e.x);break;case es:e.x=e.x<0?0:1;break;case Ac:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case Tc:e.y=e.y-Math.floor(e.y);break;case es:e.y=e.y<0?0:1;break;case Ac:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};Qn.DEFAULT_IMAGE=null;Qn.DEFAULT_MAPPING=$f;Qn.DEFAULT_ANISOTROPY=1;var _d=class _d{constructor(e=0,t=0,i=0,s=1){this.x=e,this.y=t,this.z=i,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,i,s){return this.x=e,this.y=t,this.z=i,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=this.w,o=e.elements;return this.x=o[0]*t+o[4]*i+o[8]*s+o[12]*r,this.y=o[1]*t+o[5]*i+o[9]*s+o[13]*r,this.z=o[2]*t+o[6]*i+o[10]*s+o[14]*r,this.w=o[3]*t+o[7]*i+o[11]*s+o[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,i,s,r,l=e.elements,c=l[0],h=l[4],f=l[8],u=l[1],m=l[5],g=l[9],v=l[2],d=l[6],p=l[10];if(Math.abs(h-u)<.01&&Math.abs(f-v)<.01&&Math.abs(g-d)<.01){if(Math.abs(h+u)<.1&&Math.abs(f+v)<.1&&Math.abs(g+d)<.1&&Math.abs(c+m+p-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let A=(c+1)/2,S=(m+1)/2,C=(p+1)/2,T=(h+u)/4,_=(f+v)/4,w=(g+d)/4;return A>S&&A>C?A<.01?(i=0,s=.707106781,r=.707106781):(i=Math.sqrt(A),s=T/i,r=_/i):S>C?S<.01?(i=.707106781,s=0,r=.707106781):(s=Math.sqrt(S),i=T/s,r=w/s):C<.01?(i=.707106781,s=.707106781,r=0):(r=Math.sqrt(C),i=_/r,s=w/r),this.set(i,s,r,t),this}let x=Math.sqrt((d-g)*(d-g)+(f-v)*(f-v)+(u-h)*(u-h));return Math.abs(x)<.001&&(x=1),this.x=(d-g)/x,this.y=(f-v)/x,this.z=(u-h)/x,this.w=Math.acos((c+m+p-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=bt(this.x,e.x,t.x),this.y=bt(this.y,e.y,t.y),this.z=bt(this.z,e.z,t.z),this.w=bt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=bt(this.x,e,t),this.y=bt(this.y,e,t),this.z=bt(this.z,e,t),this.w=bt(this.w,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(bt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this.w=e.w+(t.w-e.w)*i,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};_d.prototype.isVector4=!0;var rn=_d,Ic=class extends Fi{constructor(e=1,t=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Zn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=i.depth,this.scissor=new rn(0,0,e,t),this.scissorTest=!1,this.viewport=new rn(0,0,e,t),this.textures=[];let s=i.count;for(let r=0;r<s;r++)this.textures[r]=new Qn({width:e,height:t,depth:i.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(e={}){let t={minFilter:Zn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,i=1){if(this.width!==e||this.height!==t||this.depth!==i){this.width=e,this.height=t,this.depth=i;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=i,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,i=e.textures.length;t<i;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;let s=Object.assign({},e.textures[t].image);this.textures[t].source=new Ro(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){let t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},_i=class extends Ic{constructor(e=1,t=1,i={}){super(e,t,i),this.isWebGLRenderTarget=!0}},Ra=class extends Qn{constructor(e=null,t=1,i=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Dn,this.minFilter=Dn,this.wrapR=es,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var Pc=class extends Qn{constructor(e=null,t=1,i=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Dn,this.minFilter=Dn,this.wrapR=es,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}};var Qc=class Qc{constructor(e,t,i,s,r,o,a,l,c,h,f,u,m,g,v,d){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,l,c,h,f,u,m,g,v,d)}set(e,t,i,s,r,o,a,l,c,h,f,u,m,g,v,d){let p=this.elements;return p[0]=e,p[4]=t,p[8]=i,p[12]=s,p[1]=r,p[5]=o,p[9]=a,p[13]=l,p[2]=c,p[6]=h,p[10]=f,p[14]=u,p[3]=m,p[7]=g,p[11]=v,p[15]=d,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Qc().fromArray(this.elements)}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],t[9]=i[9],t[10]=i[10],t[11]=i[11],t[12]=i[12],t[13]=i[13],t[14]=i[14],t[15]=i[15],this}copyPosition(e){let t=this.elements,i=e.elements;return t[12]=i[12],t[13]=i[13],t[14]=i[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,i){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),i.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(e,t,i){return this.set(e.x,t.x,i.x,0,e.y,t.y,i.y,0,e.z,t.z,i.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();let t=this.elements,i=e.elements,s=1/uo.setFromMatrixColumn(e,0).length(),r=1/uo.setFromMatrixColumn(e,1).length(),o=1/uo.setFromMatrixColumn(e,2).length();return t[0]=i[0]*s,t[1]=i[1]*s,t[2]=i[2]*s,t[3]=0,t[4]=i[4]*r,t[5]=i[5]*r,t[6]=i[6]*r,t[7]=0,t[8]=i[8]*o,t[9]=i[9]*o,t[10]=i[10]*o,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,i=e.x,s=e.y,r=e.z,o=Math.cos(i),a=Math.sin(i),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),f=Math.sin(r);if(e.order==="XYZ"){let u=o*h,m=o*f,g=a*h,v=a*f;t[0]=l*h,t[4]=-l*f,t[8]=c,t[1]=m+g*c,t[5]=u-v*c,t[9]=-a*l,t[2]=v-u*c,t[6]=g+m*c,t[10]=o*l}else if(e.order==="YXZ"){let u=l*h,m=l*f,g=c*h,v=c*f;t[0]=u+v*a,t[4]=g*a-m,t[8]=o*c,t[1]=o*f,t[5]=o*h,t[9]=-a,t[2]=m*a-g,t[6]=v+u*a,t[10]=o*l}else if(e.order==="ZXY"){let u=l*h,m=l*f,g=c*h,v=c*f;t[0]=u-v*a,t[4]=-o*f,t[8]=g+m*a,t[1]=m+g*a,t[5]=o*h,t[9]=v-u*a,t[2]=-o*c,t[6]=a,t[10]=o*l}else if(e.order==="ZYX"){let u=o*h,m=o*f,g=a*h,v=a*f;t[0]=l*h,t[4]=g*c-m,t[8]=u*c+v,t[1]=l*f,t[5]=v*c+u,t[9]=m*c-g,t[2]=-c,t[6]=a*l,t[10]=o*l}else if(e.order==="YZX"){let u=o*l,m=o*c,g=a*l,v=a*c;t[0]=l*h,t[4]=v-u*f,t[8]=g*f+m,t[1]=f,t[5]=o*h,t[9]=-a*h,t[2]=-c*h,t[6]=m*f+g,t[10]=u-v*f}else if(e.order==="XZY"){let u=o*l,m=o*c,g=a*l,v=a*c;t[0]=l*h,t[4]=-f,t[8]=c*h,t[1]=u*f+v,t[5]=o*h,t[9]=m*f-g,t[2]=g*f-m,t[6]=a*h,t[10]=v*f+u}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(zv,e,Gv)}lookAt(e,t,i){let s=this.elements;return ui.subVectors(e,t),ui.lengthSq()===0&&(ui.z=1),ui.normalize(),$s.crossVectors(i,ui),$s.lengthSq()===0&&(Math.abs(i.z)===1?ui.x+=1e-4:ui.z+=1e-4,ui.normalize(),$s.crossVectors(i,ui)),$s.normalize(),ql.crossVectors(ui,$s),s[0]=$s.x,s[4]=ql.x,s[8]=ui.x,s[1]=$s.y,s[5]=ql.y,s[9]=ui.y,s[2]=$s.z,s[6]=ql.z,s[10]=ui.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[4],l=i[8],c=i[12],h=i[1],f=i[5],u=i[9],m=i[13],g=i[2],v=i[6],d=i[10],p=i[14],x=i[3],A=i[7],S=i[11],C=i[15],T=s[0],_=s[4],w=s[8],U=s[12],N=s[1],R=s[5],G=s[9],B=s[13],L=s[2],z=s[6],q=s[10],O=s[14],re=s[3],X=s[7],$=s[11],W=s[15];return r[0]=o*T+a*N+l*L+c*re,r[4]=o*_+a*R+l*z+c*X,r[8]=o*w+a*G+l*q+c*$,r[12]=o*U+a*B+l*O+c*W,r[1]=h*T+f*N+u*L+m*re,r[5]=h*_+f*R+u*z+m*X,r[9]=h*w+f*G+u*q+m*$,r[13]=h*U+f*B+u*O+m*W,r[2]=g*T+v*N+d*L+p*re,r[6]=g*_+v*R+d*z+p*X,r[10]=g*w+v*G+d*q+p*$,r[14]=g*U+v*B+d*O+p*W,r[3]=x*T+A*N+S*L+C*re,r[7]=x*_+A*R+S*z+C*X,r[11]=x*w+A*G+S*q+C*$,r[15]=x*U+A*B+S*O+C*W,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[12],o=e[1],a=e[5],l=e[9],c=e[13],h=e[2],f=e[6],u=e[10],m=e[14],g=e[3],v=e[7],d=e[11],p=e[15],x=l*m-c*u,A=a*m-c*f,S=a*u-l*f,C=o*m-c*h,T=o*u-l*h,_=o*f-a*h;return t*(v*x-d*A+p*S)-i*(g*x-d*C+p*T)+s*(g*A-v*C+p*_)-r*(g*S-v*T+d*_)}determinantAffine(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[1],o=e[5],a=e[9],l=e[2],c=e[6],h=e[10];return t*(o*h-a*c)-i*(r*h-a*l)+s*(r*c-o*l)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,i){let s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=i),this}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8],f=e[9],u=e[10],m=e[11],g=e[12],v=e[13],d=e[14],p=e[15],x=t*a-i*o,A=t*l-s*o,S=t*c-r*o,C=i*l-s*a,T=i*c-r*a,_=s*c-r*l,w=h*v-f*g,U=h*d-u*g,N=h*p-m*g,R=f*d-u*v,G=f*p-m*v,B=u*p-m*d,L=x*B-A*G+S*R+C*N-T*U+_*w;if(L===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let z=1/L;return e[0]=(a*B-l*G+c*R)*z,e[1]=(s*G-i*B-r*R)*z,e[2]=(v*_-d*T+p*C)*z,e[3]=(u*T-f*_-m*C)*z,e[4]=(l*N-o*B-c*U)*z,e[5]=(t*B-s*N+r*U)*z,e[6]=(d*S-g*_-p*A)*z,e[7]=(h*_-u*S+m*A)*z,e[8]=(o*G-a*N+c*w)*z,e[9]=(i*N-t*G-r*w)*z,e[10]=(g*T-v*S+p*x)*z,e[11]=(f*S-h*T-m*x)*z,e[12]=(a*U-o*R-l*w)*z,e[13]=(t*R-i*U+s*w)*z,e[14]=(v*A-g*C-d*x)*z,e[15]=(h*C-f*A+u*x)*z,this}scale(e){let t=this.elements,i=e.x,s=e.y,r=e.z;return t[0]*=i,t[4]*=s,t[8]*=r,t[1]*=i,t[5]*=s,t[9]*=r,t[2]*=i,t[6]*=s,t[10]*=r,t[3]*=i,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],i=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,i,s))}makeTranslation(e,t,i){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,i,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),i=Math.sin(e);return this.set(1,0,0,0,0,t,-i,0,0,i,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,0,i,0,0,1,0,0,-i,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,0,i,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let i=Math.cos(t),s=Math.sin(t),r=1-i,o=e.x,a=e.y,l=e.z,c=r*o,h=r*a;return this.set(c*o+i,c*a-s*l,c*l+s*a,0,c*a+s*l,h*a+i,h*l-s*o,0,c*l-s*a,h*l+s*o,r*l*l+i,0,0,0,0,1),this}makeScale(e,t,i){return this.set(e,0,0,0,0,t,0,0,0,0,i,0,0,0,0,1),this}makeShear(e,t,i,s,r,o){return this.set(1,i,r,0,e,1,o,0,t,s,1,0,0,0,0,1),this}compose(e,t,i){let s=this.elements,r=t._x,o=t._y,a=t._z,l=t._w,c=r+r,h=o+o,f=a+a,u=r*c,m=r*h,g=r*f,v=o*h,d=o*f,p=a*f,x=l*c,A=l*h,S=l*f,C=i.x,T=i.y,_=i.z;return s[0]=(1-(v+p))*C,s[1]=(m+S)*C,s[2]=(g-A)*C,s[3]=0,s[4]=(m-S)*T,s[5]=(1-(u+p))*T,s[6]=(d+x)*T,s[7]=0,s[8]=(g+A)*_,s[9]=(d-x)*_,s[10]=(1-(u+v))*_,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,i){let s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];let r=this.determinantAffine();if(r===0)return i.set(1,1,1),t.identity(),this;let o=uo.set(s[0],s[1],s[2]).length(),a=uo.set(s[4],s[5],s[6]).length(),l=uo.set(s[8],s[9],s[10]).length();r<0&&(o=-o),Di.copy(this);let c=1/o,h=1/a,f=1/l;return Di.elements[0]*=c,Di.elements[1]*=c,Di.elements[2]*=c,Di.elements[4]*=h,Di.elements[5]*=h,Di.elements[6]*=h,Di.elements[8]*=f,Di.elements[9]*=f,Di.elements[10]*=f,t.setFromRotationMatrix(Di),i.x=o,i.y=a,i.z=l,this}makePerspective(e,t,i,s,r,o,a=Ti,l=!1){let c=this.elements,h=2*r/(t-e),f=2*r/(i-s),u=(t+e)/(t-e),m=(i+s)/(i-s),g,v;if(l)g=r/(o-r),v=o*r/(o-r);else if(a===Ti)g=-(o+r)/(o-r),v=-2*o*r/(o-r);else if(a===Ta)g=-o/(o-r),v=-o*r/(o-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+a);return c[0]=h,c[4]=0,c[8]=u,c[12]=0,c[1]=0,c[5]=f,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=g,c[14]=v,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,i,s,r,o,a=Ti,l=!1){let c=this.elements,h=2/(t-e),f=2/(i-s),u=-(t+e)/(t-e),m=-(i+s)/(i-s),g,v;if(l)g=1/(o-r),v=o/(o-r);else if(a===Ti)g=-2/(o-r),v=-(o+r)/(o-r);else if(a===Ta)g=-1/(o-r),v=-r/(o-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+a);return c[0]=h,c[4]=0,c[8]=0,c[12]=u,c[1]=0,c[5]=f,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=g,c[14]=v,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<16;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<16;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e[t+9]=i[9],e[t+10]=i[10],e[t+11]=i[11],e[t+12]=i[12],e[t+13]=i[13],e[t+14]=i[14],e[t+15]=i[15],e}};Qc.prototype.isMatrix4=!0;var tn=Qc,uo=new J,Di=new tn,zv=new J(0,0,0),Gv=new J(1,1,1),$s=new J,ql=new J,ui=new J,Cg=new tn,Ig=new gi,js=class n{constructor(e=0,t=0,i=0,s=n.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=i,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,i,s=this._order){return this._x=e,this._y=t,this._z=i,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,i=!0){let s=e.elements,r=s[0],o=s[4],a=s[8],l=s[1],c=s[5],h=s[9],f=s[2],u=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(bt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-o,r)):(this._x=Math.atan2(u,c),this._z=0);break;case"YXZ":this._x=Math.asin(-bt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(a,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-f,r),this._z=0);break;case"ZXY":this._x=Math.asin(bt(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(-f,m),this._z=Math.atan2(-o,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-bt(f,-1,1)),Math.abs(f)<.9999999?(this._x=Math.atan2(u,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-o,c));break;case"YZX":this._z=Math.asin(bt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-f,r)):(this._x=0,this._y=Math.atan2(a,m));break;case"XZY":this._z=Math.asin(-bt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(u,c),this._y=Math.atan2(a,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:je("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,i===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,i){return Cg.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Cg,t,i)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return Ig.setFromEuler(this),this.setFromQuaternion(Ig,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};js.DEFAULT_ORDER="XYZ";var Ca=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},Hv=0,Pg=new J,fo=new gi,_s=new tn,Yl=new J,ma=new J,Vv=new J,Wv=new gi,Lg=new J(1,0,0),Ng=new J(0,1,0),Dg=new J(0,0,1),Ug={type:"added"},Xv={type:"removed"},po={type:"childadded",child:null},cf={type:"childremoved",child:null},ei=class n extends Fi{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Hv++}),this.uuid=ko(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=n.DEFAULT_UP.clone();let e=new J,t=new js,i=new gi,s=new J(1,1,1);function r(){i.setFromEuler(t,!1)}function o(){t.setFromQuaternion(i,void 0,!1)}t._onChange(r),i._onChange(o),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new tn},normalMatrix:{value:new lt}}),this.matrix=new tn,this.matrixWorld=new tn,this.matrixAutoUpdate=n.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=n.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Ca,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return fo.setFromAxisAngle(e,t),this.quaternion.multiply(fo),this}rotateOnWorldAxis(e,t){return fo.setFromAxisAngle(e,t),this.quaternion.premultiply(fo),this}rotateX(e){return this.rotateOnAxis(Lg,e)}rotateY(e){return this.rotateOnAxis(Ng,e)}rotateZ(e){return this.rotateOnAxis(Dg,e)}translateOnAxis(e,t){return Pg.copy(e).applyQuaternion(this.quaternion),this.position.add(Pg.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(Lg,e)}translateY(e){return this.translateOnAxis(Ng,e)}translateZ(e){return this.translateOnAxis(Dg,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(_s.copy(this.matrixWorld).invert())}lookAt(e,t,i){e.isVector3?Yl.copy(e):Yl.set(e,t,i);let s=this.parent;this.updateWorldMatrix(!0,!1),ma.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?_s.lookAt(ma,Yl,this.up):_s.lookAt(Yl,ma,this.up),this.quaternion.setFromRotationMatrix(_s),s&&(_s.extractRotation(s.matrixWorld),fo.setFromRotationMatrix(_s),this.quaternion.premultiply(fo.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(at("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(Ug),po.child=e,this.dispatchEvent(po),po.child=null):at("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(Xv),cf.child=e,this.dispatchEvent(cf),cf.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),_s.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),_s.multiply(e.parent.matrixWorld)),e.applyMatrix4(_s),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(Ug),po.child=e,this.dispatchEvent(po),po.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let i=0,s=this.children.length;i<s;i++){let o=this.children[i].getObjectByProperty(e,t);if(o!==void 0)return o}}getObjectsByProperty(e,t,i=[]){this[e]===t&&i.push(this);let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].getObjectsByProperty(e,t,i);return i}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ma,e,Vv),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ma,Wv,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let e=this.pivot;if(e!==null){let t=e.x,i=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*i-r[8]*s,r[13]+=i-r[1]*t-r[5]*i-r[9]*s,r[14]+=s-r[2]*t-r[6]*i-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].updateMatrixWorld(e)}updateWorldMatrix(e,t,i=!1){let s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),t===!0){let r=this.children;for(let o=0,a=r.length;o<a;o++)r[o].updateWorldMatrix(!1,!0,i)}}toJSON(e){let t=e===void 0||typeof e=="string",i={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(a=>({...a,boundingBox:a.boundingBox?a.boundingBox.toJSON():void 0,boundingSphere:a.boundingSphere?a.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(a=>({...a})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(a,l){return a[l.uuid]===void 0&&(a[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);let a=this.geometry.parameters;if(a!==void 0&&a.shapes!==void 0){let l=a.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){let f=l[c];r(e.shapes,f)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let a=[];for(let l=0,c=this.material.length;l<c;l++)a.push(r(e.materials,this.material[l]));s.material=a}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let a=0;a<this.children.length;a++)s.children.push(this.children[a].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let a=0;a<this.animations.length;a++){let l=this.animations[a];s.animations.push(r(e.animations,l))}}if(t){let a=o(e.geometries),l=o(e.materials),c=o(e.textures),h=o(e.images),f=o(e.shapes),u=o(e.skeletons),m=o(e.animations),g=o(e.nodes);a.length>0&&(i.geometries=a),l.length>0&&(i.materials=l),c.length>0&&(i.textures=c),h.length>0&&(i.images=h),f.length>0&&(i.shapes=f),u.length>0&&(i.skeletons=u),m.length>0&&(i.animations=m),g.length>0&&(i.nodes=g)}return i.object=s,i;function o(a){let l=[];for(let c in a){let h=a[c];delete h.metadata,l.push(h)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let i=0;i<e.children.length;i++){let s=e.children[i];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};ei.DEFAULT_UP=new J(0,1,0);ei.DEFAULT_MATRIX_AUTO_UPDATE=!0;ei.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var Cr=class extends ei{constructor(){super(),this.isGroup=!0,this.type="Group"}},$v={type:"move"},Co=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Cr,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Cr,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new J,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new J),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Cr,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new J,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new J,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let i of e.hand.values())this._getHandJoint(t,i)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,i){let s=null,r=null,o=null,a=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){o=!0;for(let v of e.hand.values()){let d=t.getJointPose(v,i),p=this._getHandJoint(c,v);d!==null&&(p.matrix.fromArray(d.transform.matrix),p.matrix.decompose(p.position,p.quaternion,p.scale),p.matrixWorldNeedsUpdate=!0,p.jointRadius=d.radius),p.visible=d!==null}let h=c.joints["index-finger-tip"],f=c.joints["thumb-tip"],u=h.position.distanceTo(f.position),m=.02,g=.005;c.inputState.pinching&&u>m+g?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&u<=m-g&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,i),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));a!==null&&(s=t.getPose(e.targetRaySpace,i),s===null&&r!==null&&(s=r),s!==null&&(a.matrix.fromArray(s.transform.matrix),a.matrix.decompose(a.position,a.quaternion,a.scale),a.matrixWorldNeedsUpdate=!0,s.linearVelocity?(a.hasLinearVelocity=!0,a.linearVelocity.copy(s.linearVelocity)):a.hasLinearVelocity=!1,s.angularVelocity?(a.hasAngularVelocity=!0,a.angularVelocity.copy(s.angularVelocity)):a.hasAngularVelocity=!1,this.dispatchEvent($v)))}return a!==null&&(a.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=o!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let i=new Cr;i.matrixAutoUpdate=!1,i.visible=!1,e.joints[t.jointName]=i,e.add(i)}return e.joints[t.jointName]}},F0={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},qs={h:0,s:0,l:0},Zl={h:0,s:0,l:0};function hf(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}var _t=class{constructor(e,t,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,i)}set(e,t,i){if(t===void 0&&i===void 0){let s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,i);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=di){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,At.colorSpaceToWorking(this,t),this}setRGB(e,t,i,s=At.workingColorSpace){return this.r=e,this.g=t,this.b=i,At.colorSpaceToWorking(this,s),this}setHSL(e,t,i,s=At.workingColorSpace){if(e=od(e,1),t=bt(t,0,1),i=bt(i,0,1),t===0)this.r=this.g=this.b=i;else{let r=i<=.5?i*(1+t):i+t-i*t,o=2*i-r;this.r=hf(o,r,e+1/3),this.g=hf(o,r,e),this.b=hf(o,r,e-1/3)}return At.colorSpaceToWorking(this,s),this}setStyle(e,t=di){function i(r){r!==void 0&&parseFloat(r)<1&&je("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r,o=s[1],a=s[2];switch(o){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:je("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){let r=s[1],o=r.length;if(o===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(o===6)return this.setHex(parseInt(r,16),t);je("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=di){let i=F0[e.toLowerCase()];return i!==void 0?this.setHex(i,t):je("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=Ss(e.r),this.g=Ss(e.g),this.b=Ss(e.b),this}copyLinearToSRGB(e){return this.r=wo(e.r),this.g=wo(e.g),this.b=wo(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=di){return At.workingToColorSpace(zn.copy(this),e),Math.round(bt(zn.r*255,0,255))*65536+Math.round(bt(zn.g*255,0,255))*256+Math.round(bt(zn.b*255,0,255))}getHexString(e=di){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=At.workingColorSpace){At.workingToColorSpace(zn.copy(this),t);let i=zn.r,s=zn.g,r=zn.b,o=Math.max(i,s,r),a=Math.min(i,s,r),l,c,h=(a+o)/2;if(a===o)l=0,c=0;else{let f=o-a;switch(c=h<=.5?f/(o+a):f/(2-o-a),o){case i:l=(s-r)/f+(s<r?6:0);break;case s:l=(r-i)/f+2;break;case r:l=(i-s)/f+4;break}l/=6}return e.h=l,e.s=c,e.l=h,e}getRGB(e,t=At.workingColorSpace){return At.workingToColorSpace(zn.copy(this),t),e.r=zn.r,e.g=zn.g,e.b=zn.b,e}getStyle(e=di){At.workingToColorSpace(zn.copy(this),e);let t=zn.r,i=zn.g,s=zn.b;return e!==di?`color(${e} ${t.toFixed(3)} ${i.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(i*255)},${Math.round(s*255)})`}offsetHSL(e,t,i){return this.getHSL(qs),this.setHSL(qs.h+e,qs.s+t,qs.l+i)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,i){return this.r=e.r+(t.r-e.r)*i,this.g=e.g+(t.g-e.g)*i,this.b=e.b+(t.b-e.b)*i,this}lerpHSL(e,t){this.getHSL(qs),e.getHSL(Zl);let i=Sa(qs.h,Zl.h,t),s=Sa(qs.s,Zl.s,t),r=Sa(qs.l,Zl.l,t);return this.setHSL(i,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,i=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*i+r[6]*s,this.g=r[1]*t+r[4]*i+r[7]*s,this.b=r[2]*t+r[5]*i+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},zn=new _t;_t.NAMES=F0;var Ia=class extends ei{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new js,this.environmentIntensity=1,this.environmentRotation=new js,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}},Ui=new J,ys=new J,uf=new J,xs=new J,mo=new J,go=new J,Og=new J,ff=new J,df=new J,pf=new J,mf=new rn,gf=new rn,_f=new rn,Js=class n{constructor(e=new J,t=new J,i=new J){this.a=e,this.b=t,this.c=i}static getNormal(e,t,i,s){s.subVectors(i,t),Ui.subVectors(e,t),s.cross(Ui);let r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,i,s,r){Ui.subVectors(s,t),ys.subVectors(i,t),uf.subVectors(e,t);let o=Ui.dot(Ui),a=Ui.dot(ys),l=Ui.dot(uf),c=ys.dot(ys),h=ys.dot(uf),f=o*c-a*a;if(f===0)return r.set(0,0,0),null;let u=1/f,m=(c*l-a*h)*u,g=(o*h-a*l)*u;return r.set(1-m-g,g,m)}static containsPoint(e,t,i,s){return this.getBarycoord(e,t,i,s,xs)===null?!1:xs.x>=0&&xs.y>=0&&xs.x+xs.y<=1}static getInterpolation(e,t,i,s,r,o,a,l){return this.getBarycoord(e,t,i,s,xs)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,xs.x),l.addScaledVector(o,xs.y),l.addScaledVector(a,xs.z),l)}static getInterpolatedAttribute(e,t,i,s,r,o){return mf.setScalar(0),gf.setScalar(0),_f.setScalar(0),mf.fromBufferAttribute(e,t),gf.fromBufferAttribute(e,i),_f.fromBufferAttribute(e,s),o.setScalar(0),o.addScaledVector(mf,r.x),o.addScaledVector(gf,r.y),o.addScaledVector(_f,r.z),o}static isFrontFacing(e,t,i,s){return Ui.subVectors(i,t),ys.subVectors(e,t),Ui.cross(ys).dot(s)<0}set(e,t,i){return this.a.copy(e),this.b.copy(t),this.c.copy(i),this}setFromPointsAndIndices(e,t,i,s){return this.a.copy(e[t]),this.b.copy(e[i]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,i,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,i),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Ui.subVectors(this.c,this.b),ys.subVectors(this.a,this.b),Ui.cross(ys).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return n.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return n.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,i,s,r){return n.getInterpolation(e,this.a,this.b,this.c,t,i,s,r)}containsPoint(e){return n.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return n.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let i=this.a,s=this.b,r=this.c,o,a;mo.subVectors(s,i),go.subVectors(r,i),ff.subVectors(e,i);let l=mo.dot(ff),c=go.dot(ff);if(l<=0&&c<=0)return t.copy(i);df.subVectors(e,s);let h=mo.dot(df),f=go.dot(df);if(h>=0&&f<=h)return t.copy(s);let u=l*f-h*c;if(u<=0&&l>=0&&h<=0&&l-h>0)return o=l/(l-h),t.copy(i).addScaledVector(mo,o);pf.subVectors(e,r);let m=mo.dot(pf),g=go.dot(pf);if(g>=0&&m<=g)return t.copy(r);let v=m*c-l*g;if(v<=0&&c>=0&&g<=0)return a=c/(c-g),t.copy(i).addScaledVector(go,a);let d=h*g-m*f;if(d<=0&&f-h>=0&&m-g>=0)return Og.subVectors(r,s),a=(f-h)/(f-h+(m-g)),t.copy(s).addScaledVector(Og,a);let p=1/(d+v+u);return o=v*p,a=u*p,t.copy(i).addScaledVector(mo,o).addScaledVector(go,a)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},Qs=class{constructor(e=new J(1/0,1/0,1/0),t=new J(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t+=3)this.expandByPoint(Oi.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,i=e.count;t<i;t++)this.expandByPoint(Oi.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let i=Oi.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(i),this.max.copy(e).add(i),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let i=e.geometry;if(i!==void 0){let r=i.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let o=0,a=r.count;o<a;o++)e.isMesh===!0?e.getVertexPosition(o,Oi):Oi.fromBufferAttribute(r,o),Oi.applyMatrix4(e.matrixWorld),this.expandByPoint(Oi);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),Kl.copy(e.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),Kl.copy(i.boundingBox)),Kl.applyMatrix4(e.matrixWorld),this.union(Kl)}let s=e.children;for(let r=0,o=s.length;r<o;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Oi),Oi.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,i;return e.normal.x>0?(t=e.normal.x*this.min.x,i=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,i=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,i+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,i+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,i+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,i+=e.normal.z*this.min.z),t<=-e.constant&&i>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(ga),Jl.subVectors(this.max,ga),_o.subVectors(e.a,ga),yo.subVectors(e.b,ga),xo.subVectors(e.c,ga),Ys.subVectors(yo,_o),Zs.subVectors(xo,yo),Er.subVectors(_o,xo);let t=[0,-Ys.z,Ys.y,0,-Zs.z,Zs.y,0,-Er.z,Er.y,Ys.z,0,-Ys.x,Zs.z,0,-Zs.x,Er.z,0,-Er.x,-Ys.y,Ys.x,0,-Zs.y,Zs.x,0,-Er.y,Er.x,0];return!yf(t,_o,yo,xo,Jl)||(t=[1,0,0,0,1,0,0,0,1],!yf(t,_o,yo,xo,Jl))?!1:(jl.crossVectors(Ys,Zs),t=[jl.x,jl.y,jl.z],yf(t,_o,yo,xo,Jl))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Oi).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Oi).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(vs[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),vs[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),vs[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),vs[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),vs[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),vs[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),vs[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),vs[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(vs),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}},vs=[new J,new J,new J,new J,new J,new J,new J,new J],Oi=new J,Kl=new Qs,_o=new J,yo=new J,xo=new J,Ys=new J,Zs=new J,Er=new J,ga=new J,Jl=new J,jl=new J,Tr=new J;function yf(n,e,t,i,s){for(let r=0,o=n.length-3;r<=o;r+=3){Tr.fromArray(n,r);let a=s.x*Math.abs(Tr.x)+s.y*Math.abs(Tr.y)+s.z*Math.abs(Tr.z),l=e.dot(Tr),c=t.dot(Tr),h=i.dot(Tr);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>a)return!1}return!0}var xn=new J,Ql=new pt,qv=0,mi=class extends Fi{constructor(e,t,i=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:qv++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=i,this.usage=I0,this.updateRanges=[],this.gpuType=ki,this.version=0,this._normalizationScale=e!==void 0?ld(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,i){e*=this.itemSize,i*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[i+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,i=this.count;t<i;t++)Ql.fromBufferAttribute(this,t),Ql.applyMatrix3(e),this.setXY(t,Ql.x,Ql.y);else if(this.itemSize===3)for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyMatrix3(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}applyMatrix4(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyMatrix4(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyNormalMatrix(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.transformDirection(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let i=this.array[e*this.itemSize+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.array[e*this.itemSize+t]=i,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,i){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.array[e+0]=t,this.array[e+1]=i,this}setXYZ(e,t,i,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this}setXYZW(e,t,i,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):U0(e,this.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):O0(e,this.array)}};var Pa=class extends mi{constructor(e,t,i){super(new Uint16Array(e),t,i)}};var La=class extends mi{constructor(e,t,i){super(new Uint32Array(e),t,i)}};var Nn=class extends mi{constructor(e,t,i){super(new Float32Array(e),t,i)}},Yv=new Qs,_a=new J,xf=new J,er=class{constructor(e=new J,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let i=this.center;t!==void 0?i.copy(t):Yv.setFromPoints(e).getCenter(i);let s=0;for(let r=0,o=e.length;r<o;r++)s=Math.max(s,i.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let i=this.center.distanceToSquared(e);return t.copy(e),i>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;_a.subVectors(e,this.center);let t=_a.lengthSq();if(t>this.radius*this.radius){let i=Math.sqrt(t),s=(i-this.radius)*.5;this.center.addScaledVector(_a,s/i),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(xf.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(_a.copy(e.center).add(xf)),this.expandByPoint(_a.copy(e.center).sub(xf))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}},Zv=0,Ei=new tn,vf=new ei,vo=new J,fi=new Qs,ya=new Qs,Ln=new J,ti=class n extends Fi{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:Zv++}),this.uuid=ko(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(vv(e)?La:Pa)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,i=0){this.groups.push({start:e,count:t,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let i=this.attributes.normal;if(i!==void 0){let r=new lt().getNormalMatrix(e);i.applyNormalMatrix(r),i.needsUpdate=!0}let s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return Ei.makeRotationFromQuaternion(e),this.applyMatrix4(Ei),this}rotateX(e){return Ei.makeRotationX(e),this.applyMatrix4(Ei),this}rotateY(e){return Ei.makeRotationY(e),this.applyMatrix4(Ei),this}rotateZ(e){return Ei.makeRotationZ(e),this.applyMatrix4(Ei),this}translate(e,t,i){return Ei.makeTranslation(e,t,i),this.applyMatrix4(Ei),this}scale(e,t,i){return Ei.makeScale(e,t,i),this.applyMatrix4(Ei),this}lookAt(e){return vf.lookAt(e),vf.updateMatrix(),this.applyMatrix4(vf.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(vo).negate(),this.translate(vo.x,vo.y,vo.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let i=[];for(let s=0,r=e.length;s<r;s++){let o=e[s];i.push(o.x,o.y,o.z||0)}this.setAttribute("position",new Nn(i,3))}else{let i=Math.min(e.length,t.count);for(let s=0;s<i;s++){let r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&je("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Qs);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){at("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new J(-1/0,-1/0,-1/0),new J(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let i=0,s=t.length;i<s;i++){let r=t[i];fi.setFromBufferAttribute(r),this.morphTargetsRelative?(Ln.addVectors(this.boundingBox.min,fi.min),this.boundingBox.expandByPoint(Ln),Ln.addVectors(this.boundingBox.max,fi.max),this.boundingBox.expandByPoint(Ln)):(this.boundingBox.expandByPoint(fi.min),this.boundingBox.expandByPoint(fi.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&at('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new er);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){at("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new J,1/0);return}if(e){let i=this.boundingSphere.center;if(fi.setFromBufferAttribute(e),t)for(let r=0,o=t.length;r<o;r++){let a=t[r];ya.setFromBufferAttribute(a),this.morphTargetsRelative?(Ln.addVectors(fi.min,ya.min),fi.expandByPoint(Ln),Ln.addVectors(fi.max,ya.max),fi.expandByPoint(Ln)):(fi.expandByPoint(ya.min),fi.expandByPoint(ya.max))}fi.getCenter(i);let s=0;for(let r=0,o=e.count;r<o;r++)Ln.fromBufferAttribute(e,r),s=Math.max(s,i.distanceToSquared(Ln));if(t)for(let r=0,o=t.length;r<o;r++){let a=t[r],l=this.morphTargetsRelative;for(let c=0,h=a.count;c<h;c++)Ln.fromBufferAttribute(a,c),l&&(vo.fromBufferAttribute(e,c),Ln.add(vo)),s=Math.max(s,i.distanceToSquared(Ln))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&at('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){at("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let i=t.position,s=t.normal,r=t.uv,o=this.getAttribute("tangent");(o===void 0||o.count!==i.count)&&(o=new mi(new Float32Array(4*i.count),4),this.setAttribute("tangent",o));let a=[],l=[],c=new Uint8Array(i.count);for(let U=0;U<i.count;U++)a[U]=new J,l[U]=new J;let h=new J,f=new J,u=new J,m=new pt,g=new pt,v=new pt,d=new J,p=new J;function x(U,N,R){c[U]=c[N]=c[R]=1,h.fromBufferAttribute(i,U),f.fromBufferAttribute(i,N),u.fromBufferAttribute(i,R),m.fromBufferAttribute(r,U),g.fromBufferAttribute(r,N),v.fromBufferAttribute(r,R),f.sub(h),u.sub(h),g.sub(m),v.sub(m);let G=1/(g.x*v.y-v.x*g.y);isFinite(G)&&(d.copy(f).multiplyScalar(v.y).addScaledVector(u,-g.y).multiplyScalar(G),p.copy(u).multiplyScalar(g.x).addScaledVector(f,-v.x).multiplyScalar(G),a[U].add(d),a[N].add(d),a[R].add(d),l[U].add(p),l[N].add(p),l[R].add(p))}let A=this.groups;A.length===0&&(A=[{start:0,count:e.count}]);for(let U=0,N=A.length;U<N;++U){let R=A[U],G=R.start,B=R.count;for(let L=G,z=G+B;L<z;L+=3)x(e.getX(L+0),e.getX(L+1),e.getX(L+2))}let S=new J,C=new J,T=new J,_=new J;function w(U){T.fromBufferAttribute(s,U),_.copy(T);let N=a[U];S.copy(N),S.sub(T.multiplyScalar(T.dot(N))).normalize(),C.crossVectors(_,N);let G=C.dot(l[U])<0?-1:1;o.setXYZW(U,S.x,S.y,S.z,G)}for(let U=0,N=i.count;U<N;++U)c[U]&&w(U);this._transformed=!0}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==t.count)i=new mi(new Float32Array(t.count*3),3),this.setAttribute("normal",i);else for(let u=0,m=i.count;u<m;u++)i.setXYZ(u,0,0,0);let s=new J,r=new J,o=new J,a=new J,l=new J,c=new J,h=new J,f=new J;if(e)for(let u=0,m=e.count;u<m;u+=3){let g=e.getX(u+0),v=e.getX(u+1),d=e.getX(u+2);s.fromBufferAttribute(t,g),r.fromBufferAttribute(t,v),o.fromBufferAttribute(t,d),h.subVectors(o,r),f.subVectors(s,r),h.cross(f),a.fromBufferAttribute(i,g),l.fromBufferAttribute(i,v),c.fromBufferAttribute(i,d),a.add(h),l.add(h),c.add(h),i.setXYZ(g,a.x,a.y,a.z),i.setXYZ(v,l.x,l.y,l.z),i.setXYZ(d,c.x,c.y,c.z)}else for(let u=0,m=t.count;u<m;u+=3)s.fromBufferAttribute(t,u+0),r.fromBufferAttribute(t,u+1),o.fromBufferAttribute(t,u+2),h.subVectors(o,r),f.subVectors(s,r),h.cross(f),i.setXYZ(u+0,h.x,h.y,h.z),i.setXYZ(u+1,h.x,h.y,h.z),i.setXYZ(u+2,h.x,h.y,h.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,i=e.count;t<i;t++)Ln.fromBufferAttribute(e,t),Ln.normalize(),e.setXYZ(t,Ln.x,Ln.y,Ln.z)}toNonIndexed(){function e(a,l){let c=a.array,h=a.itemSize,f=a.normalized,u=new c.constructor(l.length*h),m=0,g=0;for(let v=0,d=l.length;v<d;v++){a.isInterleavedBufferAttribute?m=l[v]*a.data.stride+a.offset:m=l[v]*h;for(let p=0;p<h;p++)u[g++]=c[m++]}return new mi(u,h,f)}if(this.index===null)return je("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new n,i=this.index.array,s=this.attributes;for(let a in s){let l=s[a],c=e(l,i);t.setAttribute(a,c)}let r=this.morphAttributes;for(let a in r){let l=[],c=r[a];for(let h=0,f=c.length;h<f;h++){let u=c[h],m=e(u,i);l.push(m)}t.morphAttributes[a]=l}t.morphTargetsRelative=this.morphTargetsRelative;let o=this.groups;for(let a=0,l=o.length;a<l;a++){let c=o[a];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){let e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let l=this.parameters;for(let c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let i=this.attributes;for(let l in i){let c=i[l];e.data.attributes[l]=c.toJSON(e.data)}let s={},r=!1;for(let l in this.morphAttributes){let c=this.morphAttributes[l],h=[];for(let f=0,u=c.length;f<u;f++){let m=c[f];h.push(m.toJSON(e.data))}h.length>0&&(s[l]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);let o=this.groups;o.length>0&&(e.data.groups=JSON.parse(JSON.stringify(o)));let a=this.boundingSphere;return a!==null&&(e.data.boundingSphere=a.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let i=e.index;i!==null&&this.setIndex(i.clone());let s=e.attributes;for(let c in s){let h=s[c];this.setAttribute(c,h.clone(t))}let r=e.morphAttributes;for(let c in r){let h=[],f=r[c];for(let u=0,m=f.length;u<m;u++)h.push(f[u].clone(t));this.morphAttributes[c]=h}this.morphTargetsRelative=e.morphTargetsRelative;let o=e.groups;for(let c=0,h=o.length;c<h;c++){let f=o[c];this.addGroup(f.start,f.count,f.materialIndex)}let a=e.boundingBox;a!==null&&(this.boundingBox=a.clone());let l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}};var bf=new J,Kv=new J,Jv=new lt,pi=class{constructor(e=new J(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,i,s){return this.normal.set(e,t,i),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,i){let s=bf.subVectors(i,t).cross(Kv.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,i=!0){let s=e.delta(bf),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let o=-(e.start.dot(this.normal)+this.constant)/r;return i===!0&&(o<0||o>1)?null:t.copy(e.start).addScaledVector(s,o)}intersectsLine(e){let t=this.distanceToPoint(e.start),i=this.distanceToPoint(e.end);return t<0&&i>0||i<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let i=t||Jv.getNormalMatrix(e),s=this.coplanarPoint(bf).applyMatrix4(e),r=this.normal.applyMatrix3(i).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}},jv=0,ws=class extends Fi{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:jv++}),this.uuid=ko(),this.name="",this.type="Material",this.blending=Oo,this.side=ar,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Of,this.blendDst=Ff,this.blendEquation=Lr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new _t(0,0,0),this.blendAlpha=0,this.depthFunc=Eo,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=w0,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=yc,this.stencilZFail=yc,this.stencilZPass=yc,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let i=e[t];if(i===void 0){je(`Material: parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){je(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(i):s&&s.isVector2&&i&&i.isVector2||s&&s.isEuler&&i&&i.isEuler||s&&s.isVector3&&i&&i.isVector3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(e).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(e).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(e).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(e).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(e).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function s(r){let o=[];for(let a in r){let l=r[a];delete l.metadata,o.push(l)}return o}if(t){let r=s(e.textures),o=s(e.images);r.length>0&&(i.textures=r),o.length>0&&(i.images=o)}return i}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new _t().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(i=>new pi().fromJSON(i))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let i=e.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new pt().fromArray(i)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new pt().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,i=null;if(t!==null){let s=t.length;i=new Array(s);for(let r=0;r!==s;++r)i[r]=t[r].clone()}return this.clippingPlanes=i,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}};var bs=new J,Sf=new J,ec=new J,tc=new J,tr=class{constructor(e=new J,t=new J(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,bs)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let i=t.dot(this.direction);return i<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=bs.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(bs.copy(this.origin).addScaledVector(this.direction,t),bs.distanceToSquared(e))}distanceSqToSegment(e,t,i,s){Sf.copy(e).add(t).multiplyScalar(.5),ec.copy(t).sub(e).normalize(),tc.copy(this.origin).sub(Sf);let r=e.distanceTo(t)*.5,o=-this.direction.dot(ec),a=tc.dot(this.direction),l=-tc.dot(ec),c=tc.lengthSq(),h=Math.abs(1-o*o),f,u,m,g;if(h>0)if(f=o*l-a,u=o*a-l,g=r*h,f>=0)if(u>=-g)if(u<=g){let v=1/h;f*=v,u*=v,m=f*(f+o*u+2*a)+u*(o*f+u+2*l)+c}else u=r,f=Math.max(0,-(o*u+a)),m=-f*f+u*(u+2*l)+c;else u=-r,f=Math.max(0,-(o*u+a)),m=-f*f+u*(u+2*l)+c;else u<=-g?(f=Math.max(0,-(-o*r+a)),u=f>0?-r:Math.min(Math.max(-r,-l),r),m=-f*f+u*(u+2*l)+c):u<=g?(f=0,u=Math.min(Math.max(-r,-l),r),m=u*(u+2*l)+c):(f=Math.max(0,-(o*r+a)),u=f>0?r:Math.min(Math.max(-r,-l),r),m=-f*f+u*(u+2*l)+c);else u=o>0?-r:r,f=Math.max(0,-(o*u+a)),m=-f*f+u*(u+2*l)+c;return i&&i.copy(this.origin).addScaledVector(this.direction,f),s&&s.copy(Sf).addScaledVector(ec,u),m}intersectSphere(e,t){if(e.radius<0)return null;bs.subVectors(e.center,this.origin);let i=bs.dot(this.direction),s=bs.dot(bs)-i*i,r=e.radius*e.radius;if(s>r)return null;let o=Math.sqrt(r-s),a=i-o,l=i+o;return l<0?null:a<0?this.at(l,t):this.at(a,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let i=-(this.origin.dot(e.normal)+e.constant)/t;return i>=0?i:null}intersectPlane(e,t){let i=this.distanceToPlane(e);return i===null?null:this.at(i,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let i,s,r,o,a,l,c=1/this.direction.x,h=1/this.direction.y,f=1/this.direction.z,u=this.origin;return c>=0?(i=(e.min.x-u.x)*c,s=(e.max.x-u.x)*c):(i=(e.max.x-u.x)*c,s=(e.min.x-u.x)*c),h>=0?(r=(e.min.y-u.y)*h,o=(e.max.y-u.y)*h):(r=(e.max.y-u.y)*h,o=(e.min.y-u.y)*h),i>o||r>s||((r>i||isNaN(i))&&(i=r),(o<s||isNaN(s))&&(s=o),f>=0?(a=(e.min.z-u.z)*f,l=(e.max.z-u.z)*f):(a=(e.max.z-u.z)*f,l=(e.min.z-u.z)*f),i>l||a>s)||((a>i||i!==i)&&(i=a),(l<s||s!==s)&&(s=l),s<0)?null:this.at(i>=0?i:s,t)}intersectsBox(e){return this.intersectBox(e,bs)!==null}intersectTriangle(e,t,i,s,r){let o=this.origin,a=this.direction,l=a.x,c=a.y,h=a.z,f=e.x-o.x,u=e.y-o.y,m=e.z-o.z,g=t.x-o.x,v=t.y-o.y,d=t.z-o.z,p=i.x-o.x,x=i.y-o.y,A=i.z-o.z,S=Math.abs(l),C=Math.abs(c),T=Math.abs(h),_,w,U,N,R,G,B,L,z,q,O,re;if(S>=C&&S>=T?(U=l,G=f,z=g,re=p,l>=0?(_=c,w=h,N=u,R=m,B=v,L=d,q=x,O=A):(_=h,w=c,N=m,R=u,B=d,L=v,q=A,O=x)):C>=T?(U=c,G=u,z=v,re=x,c>=0?(_=h,w=l,N=m,R=f,B=d,L=g,q=A,O=p):(_=l,w=h,N=f,R=m,B=g,L=d,q=p,O=A)):(U=h,G=m,z=d,re=A,h>=0?(_=l,w=c,N=f,R=u,B=g,L=v,q=p,O=x):(_=c,w=l,N=u,R=f,B=v,L=g,q=x,O=p)),U===0)return null;let X=_/U,$=w/U,W=1/U,ne=N-X*G,le=R-$*G,Q=B-X*z,me=L-$*z,pe=q-X*re,be=O-$*re,xe=pe*me-be*Q,We=ne*be-le*pe,Qe=Q*le-me*ne;if(s){if(xe<0||We<0||Qe<0)return null}else if((xe<0||We<0||Qe<0)&&(xe>0||We>0||Qe>0))return null;let Ne=xe+We+Qe;if(Ne===0)return null;let qe=W*(xe*G+We*z+Qe*re);return(Ne>0?qe<0:qe>0)?null:this.at(qe/Ne,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},Lc=class extends ws{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new _t(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new js,this.combine=Bf,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}},Fg=new tn,Ar=new tr,nc=new er,Bg=new J,ic=new J,sc=new J,rc=new J,Mf=new J,oc=new J,kg=new J,ac=new J,ts=class extends ei{constructor(e=new ti,t=new Lc){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}getVertexPosition(e,t){let i=this.geometry,s=i.attributes.position,r=i.morphAttributes.position,o=i.morphTargetsRelative;t.fromBufferAttribute(s,e);let a=this.morphTargetInfluences;if(r&&a){oc.set(0,0,0);for(let l=0,c=r.length;l<c;l++){let h=a[l],f=r[l];h!==0&&(Mf.fromBufferAttribute(f,e),o?oc.addScaledVector(Mf,h):oc.addScaledVector(Mf.sub(t),h))}t.add(oc)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),nc.copy(i.boundingSphere),nc.applyMatrix4(r),Ar.copy(e.ray).recast(e.near),!(nc.containsPoint(Ar.origin)===!1&&(Ar.intersectSphere(nc,Bg)===null||Ar.origin.distanceToSquared(Bg)>(e.far-e.near)**2))&&(Fg.copy(r).invert(),Ar.copy(e.ray).applyMatrix4(Fg),!(i.boundingBox!==null&&Ar.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(e,t,Ar)))}_computeIntersections(e,t,i){let s,r=this.geometry,o=this.material,a=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,f=r.attributes.normal,u=r.groups,m=r.drawRange;if(a!==null)if(Array.isArray(o))for(let g=0,v=u.length;g<v;g++){let d=u[g],p=o[d.materialIndex],x=Math.max(d.start,m.start),A=Math.min(a.count,Math.min(d.start+d.count,m.start+m.count));for(let S=x,C=A;S<C;S+=3){let T=a.getX(S),_=a.getX(S+1),w=a.getX(S+2);s=lc(this,p,e,i,c,h,f,T,_,w),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=d.materialIndex,t.push(s))}}else{let g=Math.max(0,m.start),v=Math.min(a.count,m.start+m.count);for(let d=g,p=v;d<p;d+=3){let x=a.getX(d),A=a.getX(d+1),S=a.getX(d+2);s=lc(this,o,e,i,c,h,f,x,A,S),s&&(s.faceIndex=Math.floor(d/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(o))for(let g=0,v=u.length;g<v;g++){let d=u[g],p=o[d.materialIndex],x=Math.max(d.start,m.start),A=Math.min(l.count,Math.min(d.start+d.count,m.start+m.count));for(let S=x,C=A;S<C;S+=3){let T=S,_=S+1,w=S+2;s=lc(this,p,e,i,c,h,f,T,_,w),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=d.materialIndex,t.push(s))}}else{let g=Math.max(0,m.start),v=Math.min(l.count,m.start+m.count);for(let d=g,p=v;d<p;d+=3){let x=d,A=d+1,S=d+2;s=lc(this,o,e,i,c,h,f,x,A,S),s&&(s.faceIndex=Math.floor(d/3),t.push(s))}}}};function Qv(n,e,t,i,s,r,o,a){let l;if(e.side===Kn?l=i.intersectTriangle(o,r,s,!0,a):l=i.intersectTriangle(s,r,o,e.side===ar,a),l===null)return null;ac.copy(a),ac.applyMatrix4(n.matrixWorld);let c=t.ray.origin.distanceTo(ac);return c<t.near||c>t.far?null:{distance:c,point:ac.clone(),object:n}}function lc(n,e,t,i,s,r,o,a,l,c){n.getVertexPosition(a,ic),n.getVertexPosition(l,sc),n.getVertexPosition(c,rc);let h=Qv(n,e,t,i,ic,sc,rc,kg);if(h){let f=new J;Js.getBarycoord(kg,ic,sc,rc,f),s&&(h.uv=Js.getInterpolatedAttribute(s,a,l,c,f,new pt)),r&&(h.uv1=Js.getInterpolatedAttribute(r,a,l,c,f,new pt)),o&&(h.normal=Js.getInterpolatedAttribute(o,a,l,c,f,new J),h.normal.dot(i.direction)>0&&h.normal.multiplyScalar(-1));let u={a,b:l,c,normal:new J,materialIndex:0};Js.getNormal(ic,sc,rc,u.normal),h.face=u,h.barycoord=f}return h}var Nc=class extends Qn{constructor(e=null,t=1,i=1,s,r,o,a,l,c=Dn,h=Dn,f,u){super(null,o,a,l,c,h,s,r,f,u),this.isDataTexture=!0,this.image={data:e,width:t,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var Rr=new er,eb=new pt(.5,.5),cc=new J,Ir=class{constructor(e=new pi,t=new pi,i=new pi,s=new pi,r=new pi,o=new pi){this.planes=[e,t,i,s,r,o]}set(e,t,i,s,r,o){let a=this.planes;return a[0].copy(e),a[1].copy(t),a[2].copy(i),a[3].copy(s),a[4].copy(r),a[5].copy(o),this}copy(e){let t=this.planes;for(let i=0;i<6;i++)t[i].copy(e.planes[i]);return this}setFromProjectionMatrix(e,t=Ti,i=!1){let s=this.planes,r=e.elements,o=r[0],a=r[1],l=r[2],c=r[3],h=r[4],f=r[5],u=r[6],m=r[7],g=r[8],v=r[9],d=r[10],p=r[11],x=r[12],A=r[13],S=r[14],C=r[15];if(s[0].setComponents(c-o,m-h,p-g,C-x).normalize(),s[1].setComponents(c+o,m+h,p+g,C+x).normalize(),s[2].setComponents(c+a,m+f,p+v,C+A).normalize(),s[3].setComponents(c-a,m-f,p-v,C-A).normalize(),i)s[4].setComponents(l,u,d,S).normalize(),s[5].setComponents(c-l,m-u,p-d,C-S).normalize();else if(s[4].setComponents(c-l,m-u,p-d,C-S).normalize(),t===Ti)s[5].setComponents(c+l,m+u,p+d,C+S).normalize();else if(t===Ta)s[5].setComponents(l,u,d,S).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Rr.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Rr.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Rr)}intersectsSprite(e){Rr.center.set(0,0,0);let t=eb.distanceTo(e.center);return Rr.radius=.7071067811865476+t,Rr.applyMatrix4(e.matrixWorld),this.intersectsSphere(Rr)}intersectsSphere(e){let t=this.planes,i=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(i)<s)return!1;return!0}intersectsBox(e){let t=this.planes;for(let i=0;i<6;i++){let s=t[i];if(cc.x=s.normal.x>0?e.max.x:e.min.x,cc.y=s.normal.y>0?e.max.y:e.min.y,cc.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(cc)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let i=0;i<6;i++)if(t[i].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},zg=new tn,Dc=class n{constructor(){this.coordinateSystem=Ti,this._frustums=[],this._count=0}setFromArrayCamera(e){let t=e.cameras,i=this._frustums;for(let s=0;s<t.length;s++){let r=t[s];zg.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),i[s]===void 0&&(i[s]=new Ir),i[s].setFromProjectionMatrix(zg,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsObject(e))return!0;return!1}intersectsSprite(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSprite(e))return!0;return!1}intersectsSphere(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSphere(e))return!0;return!1}intersectsBox(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsBox(e))return!0;return!1}containsPoint(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;let t=this._frustums,i=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Ir),t[s].copy(i[s]);return this._count=e._count,this}clone(){return new n().copy(this)}};var Io=class extends ws{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new _t(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}},Uc=new J,Oc=new J,Gg=new tn,xa=new tr,hc=new er,wf=new J,Hg=new J,Fc=class extends ei{constructor(e=new ti,t=new Io){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[0];for(let s=1,r=t.count;s<r;s++)Uc.fromBufferAttribute(t,s-1),Oc.fromBufferAttribute(t,s),i[s]=i[s-1],i[s]+=Uc.distanceTo(Oc);e.setAttribute("lineDistance",new Nn(i,1))}else je("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),hc.copy(i.boundingSphere),hc.applyMatrix4(s),hc.radius+=r,e.ray.intersectsSphere(hc)===!1)return;Gg.copy(s).invert(),xa.copy(e.ray).applyMatrix4(Gg);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=this.isLineSegments?2:1,h=i.index,u=i.attributes.position;if(h!==null){let m=Math.max(0,o.start),g=Math.min(h.count,o.start+o.count);for(let v=m,d=g-1;v<d;v+=c){let p=h.getX(v),x=h.getX(v+1),A=uc(this,e,xa,l,p,x,v);A&&t.push(A)}if(this.isLineLoop){let v=h.getX(g-1),d=h.getX(m),p=uc(this,e,xa,l,v,d,g-1);p&&t.push(p)}}else{let m=Math.max(0,o.start),g=Math.min(u.count,o.start+o.count);for(let v=m,d=g-1;v<d;v+=c){let p=uc(this,e,xa,l,v,v+1,v);p&&t.push(p)}if(this.isLineLoop){let v=uc(this,e,xa,l,g-1,m,g-1);v&&t.push(v)}}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function uc(n,e,t,i,s,r,o){let a=n.geometry.attributes.position;if(Uc.fromBufferAttribute(a,s),Oc.fromBufferAttribute(a,r),t.distanceSqToSegment(Uc,Oc,wf,Hg)>i)return;wf.applyMatrix4(n.matrixWorld);let c=e.ray.origin.distanceTo(wf);if(!(c<e.near||c>e.far))return{distance:c,point:Hg.clone().applyMatrix4(n.matrixWorld),index:o,face:null,faceIndex:null,barycoord:null,object:n}}var Vg=new J,Wg=new J,Na=class extends Fc{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[];for(let s=0,r=t.count;s<r;s+=2)Vg.fromBufferAttribute(t,s),Wg.fromBufferAttribute(t,s+1),i[s]=s===0?0:i[s-1],i[s+1]=i[s]+Vg.distanceTo(Wg);e.setAttribute("lineDistance",new Nn(i,1))}else je("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}};var Po=class extends ws{constructor(e){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new _t(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.size=e.size,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}},Xg=new tn,Cf=new tr,fc=new er,dc=new J,Da=class extends ei{constructor(e=new ti,t=new Po){super(),this.isPoints=!0,this.type="Points",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Points.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),fc.copy(i.boundingSphere),fc.applyMatrix4(s),fc.radius+=r,e.ray.intersectsSphere(fc)===!1)return;Xg.copy(s).invert(),Cf.copy(e.ray).applyMatrix4(Xg);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=i.index,f=i.attributes.position;if(c!==null){let u=Math.max(0,o.start),m=Math.min(c.count,o.start+o.count);for(let g=u,v=m;g<v;g++){let d=c.getX(g);dc.fromBufferAttribute(f,d),$g(dc,d,l,s,e,t,this)}}else{let u=Math.max(0,o.start),m=Math.min(f.count,o.start+o.count);for(let g=u,v=m;g<v;g++)dc.fromBufferAttribute(f,g),$g(dc,g,l,s,e,t,this)}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function $g(n,e,t,i,s,r,o){let a=Cf.distanceSqToPoint(n);if(a<t){let l=new J;Cf.closestPointToPoint(n,l),l.applyMatrix4(i);let c=s.ray.origin.distanceTo(l);if(c<s.near||c>s.far)return;r.push({distance:c,distanceToRay:Math.sqrt(a),point:l,index:e,face:null,faceIndex:null,barycoord:null,object:o})}}var Ua=class extends Qn{constructor(e=[],t=Nr,i,s,r,o,a,l,c,h){super(e,t,i,s,r,o,a,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}};var Es=class extends Qn{constructor(e,t,i=Bi,s,r,o,a=Dn,l=Dn,c,h=Ms,f=1){if(h!==Ms&&h!==As)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let u={width:e,height:t,depth:f};super(u,s,r,o,a,l,h,i,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Ro(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}},Oa=class extends Es{constructor(e,t=Bi,i=Nr,s,r,o=Dn,a=Dn,l,c=Ms){let h={width:e,height:e,depth:1},f=[h,h,h,h,h,h];super(e,e,t,i,s,r,o,a,l,c),this.image=f,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}},Fa=class extends Qn{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}},Lo=class n extends ti{constructor(e=1,t=1,i=1,s=1,r=1,o=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:i,widthSegments:s,heightSegments:r,depthSegments:o};let a=this;s=Math.floor(s),r=Math.floor(r),o=Math.floor(o);let l=[],c=[],h=[],f=[],u=0,m=0;g("z","y","x",-1,-1,i,t,e,o,r,0),g("z","y","x",1,-1,i,t,-e,o,r,1),g("x","z","y",1,1,e,i,t,s,o,2),g("x","z","y",1,-1,e,i,-t,s,o,3),g("x","y","z",1,-1,e,t,i,s,r,4),g("x","y","z",-1,-1,e,t,-i,s,r,5),this.setIndex(l),this.setAttribute("position",new Nn(c,3)),this.setAttribute("normal",new Nn(h,3)),this.setAttribute("uv",new Nn(f,2));function g(v,d,p,x,A,S,C,T,_,w,U){let N=S/_,R=C/w,G=S/2,B=C/2,L=T/2,z=_+1,q=w+1,O=0,re=0,X=new J;for(let $=0;$<q;$++){let W=$*R-B;for(let ne=0;ne<z;ne++){let le=ne*N-G;X[v]=le*x,X[d]=W*A,X[p]=L,c.push(X.x,X.y,X.z),X[v]=0,X[d]=0,X[p]=T>0?1:-1,h.push(X.x,X.y,X.z),f.push(ne/_),f.push(1-$/w),O+=1}}for(let $=0;$<w;$++)for(let W=0;W<_;W++){let ne=u+W+z*$,le=u+W+z*($+1),Q=u+(W+1)+z*($+1),me=u+(W+1)+z*$;l.push(ne,le,me),l.push(le,Q,me),re+=6}a.addGroup(m,re,U),m+=re,u+=O}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};var Ba=class n extends ti{constructor(e=1,t=1,i=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:i,heightSegments:s};let r=e/2,o=t/2,a=Math.floor(i),l=Math.floor(s),c=a+1,h=l+1,f=e/a,u=t/l,m=[],g=[],v=[],d=[];for(let p=0;p<h;p++){let x=p*u-o;for(let A=0;A<c;A++){let S=A*f-r;g.push(S,-x,0),v.push(0,0,1),d.push(A/a),d.push(1-p/l)}}for(let p=0;p<l;p++)for(let x=0;x<a;x++){let A=x+c*p,S=x+c*(p+1),C=x+1+c*(p+1),T=x+1+c*p;m.push(A,S,T),m.push(S,C,T)}this.setIndex(m),this.setAttribute("position",new Nn(g,3)),this.setAttribute("normal",new Nn(v,3)),this.setAttribute("uv",new Nn(d,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.widthSegments,e.heightSegments)}};function Ur(n){let e={};for(let t in n){e[t]={};for(let i in n[t]){let s=n[t][i];if(qg(s))s.isRenderTargetTexture?(je("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][i]=null):e[t][i]=s.clone();else if(Array.isArray(s))if(qg(s[0])){let r=[];for(let o=0,a=s.length;o<a;o++)r[o]=s[o].clone();e[t][i]=r}else e[t][i]=s.slice();else e[t][i]=s}}return e}function Gn(n){let e={};for(let t=0;t<n.length;t++){let i=Ur(n[t]);for(let s in i)e[s]=i[s]}return e}function qg(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function tb(n){let e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function hd(n){let e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:At.workingColorSpace}var B0={clone:Ur,merge:Gn},nb=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,ib=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,ns=class extends ws{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=nb,this.fragmentShader=ib,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Ur(e.uniforms),this.uniformsGroups=tb(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let s in this.uniforms){let o=this.uniforms[s].value;o&&o.isTexture?t.uniforms[s]={type:"t",value:o.toJSON(e).uuid}:o&&o.isColor?t.uniforms[s]={type:"c",value:o.getHex()}:o&&o.isVector2?t.uniforms[s]={type:"v2",value:o.toArray()}:o&&o.isVector3?t.uniforms[s]={type:"v3",value:o.toArray()}:o&&o.isVector4?t.uniforms[s]={type:"v4",value:o.toArray()}:o&&o.isMatrix3?t.uniforms[s]={type:"m3",value:o.toArray()}:o&&o.isMatrix4?t.uniforms[s]={type:"m4",value:o.toArray()}:t.uniforms[s]={value:o}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let i={};for(let s in this.extensions)this.extensions[s]===!0&&(i[s]=!0);return Object.keys(i).length>0&&(t.extensions=i),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(let i in e.uniforms){let s=e.uniforms[i];switch(this.uniforms[i]={},s.type){case"t":this.uniforms[i].value=t[s.value]||null;break;case"c":this.uniforms[i].value=new _t().setHex(s.value);break;case"v2":this.uniforms[i].value=new pt().fromArray(s.value);break;case"v3":this.uniforms[i].value=new J().fromArray(s.value);break;case"v4":this.uniforms[i].value=new rn().fromArray(s.value);break;case"m3":this.uniforms[i].value=new lt().fromArray(s.value);break;case"m4":this.uniforms[i].value=new tn().fromArray(s.value);break;default:this.uniforms[i].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(let i in e.extensions)this.extensions[i]=e.extensions[i];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}},Bc=class extends ns{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}};var kc=class extends ws{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=S0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},zc=class extends ws{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}};function bo(n,e){return!n||n.constructor===e?n:typeof e.BYTES_PER_ELEMENT=="number"?new e(n):Array.prototype.slice.call(n)}function pc(n){return n!==void 0&&n.inTangents!==void 0&&n.outTangents!==void 0}var nr=class{constructor(e,t,i,s){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=s!==void 0?s:new t.constructor(i),this.sampleValues=t,this.valueSize=i,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,i=this._cachedIndex,s=t[i],r=t[i-1];n:{e:{let o;t:{i:if(!(e<s)){for(let a=i+2;;){if(s===void 0){if(e<r)break i;return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}if(i===a)break;if(r=s,s=t[++i],e<s)break e}o=t.length;break t}if(!(e>=r)){let a=t[1];e<a&&(i=2,r=a);for(let l=i-2;;){if(r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(i===l)break;if(s=r,r=t[--i-1],e>=r)break e}o=i,i=0;break t}break n}for(;i<o;){let a=i+o>>>1;e<t[a]?o=a:i=a+1}if(s=t[i],r=t[i-1],r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(s===void 0)return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}this._cachedIndex=i,this.intervalChanged_(i,r,s)}return this.interpolate_(i,r,e,s)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,i=this.sampleValues,s=this.valueSize,r=e*s;for(let o=0;o!==s;++o)t[o]=i[r+o];return t}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},Gc=class extends nr{constructor(e,t,i,s){super(e,t,i,s),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:Tf,endingEnd:Tf}}intervalChanged_(e,t,i){let s=this.parameterPositions,r=e-2,o=e+1,a=s[r],l=s[o];if(a===void 0)switch(this.getSettings_().endingStart){case Af:r=e,a=2*t-i;break;case Rf:r=s.length-2,a=t+s[r]-s[r+1];break;default:r=e,a=i}if(l===void 0)switch(this.getSettings_().endingEnd){case Af:o=e,l=2*i-t;break;case Rf:o=1,l=i+s[1]-s[0];break;default:o=e-1,l=t}let c=(i-t)*.5,h=this.valueSize;this._weightPrev=c/(t-a),this._weightNext=c/(l-i),this._offsetPrev=r*h,this._offsetNext=o*h}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=this._offsetPrev,f=this._offsetNext,u=this._weightPrev,m=this._weightNext,g=(i-t)/(s-t),v=g*g,d=v*g,p=-u*d+2*u*v-u*g,x=(1+u)*d+(-1.5-2*u)*v+(-.5+u)*g+1,A=(-1-m)*d+(1.5+m)*v+.5*g,S=m*d-m*v;for(let C=0;C!==a;++C)r[C]=p*o[h+C]+x*o[c+C]+A*o[l+C]+S*o[f+C];return r}},Hc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=(i-t)/(s-t),f=1-h;for(let u=0;u!==a;++u)r[u]=o[c+u]*f+o[l+u]*h;return r}},Vc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e){return this.copySampleValue_(e-1)}},Wc=class extends nr{interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=this.inTangents,f=this.outTangents;if(!h||!f){let g=(i-t)/(s-t),v=1-g;for(let d=0;d!==a;++d)r[d]=o[c+d]*v+o[l+d]*g;return r}let u=a*2,m=e-1;for(let g=0;g!==a;++g){let v=o[c+g],d=o[l+g],p=m*u+g*2,x=f[p],A=f[p+1],S=e*u+g*2,C=h[S],T=h[S+1],_=rb(i,t,x,C,s);r[g]=k0(_,v,A,T,d)}return r}};function k0(n,e,t,i,s){let r=1-n;return r*r*r*e+3*r*r*n*t+3*r*n*n*i+n*n*n*s}function sb(n,e,t,i,s){let r=1-n;return 3*r*r*(t-e)+6*r*n*(i-t)+3*n*n*(s-i)}function rb(n,e,t,i,s){let r=(n-e)/(s-e);for(let o=0;o<8;o++){let a=k0(r,e,t,i,s)-n;if(Math.abs(a)<1e-10)break;let l=sb(r,e,t,i,s);if(Math.abs(l)<1e-10)break;r=Math.max(0,Math.min(1,r-a/l))}return r}var yi=class{constructor(e,t,i,s){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=bo(t,this.TimeBufferType),this.values=bo(i,this.ValueBufferType),this.setInterpolation(s||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,i;if(t.toJSON!==this.toJSON)i=t.toJSON(e);else{i={name:e.name,times:bo(e.times,Array),values:bo(e.values,Array)};let s=e.getInterpolation();s!==e.DefaultInterpolation&&(i.interpolation=s),pc(e.settings)&&(i.settings={inTangents:bo(e.settings.inTangents,Array),outTangents:bo(e.settings.outTangents,Array)})}return i.type=e.ValueTypeName,i}InterpolantFactoryMethodDiscrete(e){return new Vc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new Hc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new Gc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodBezier(e){let t=new Wc(this.times,this.values,this.getValueSize(),e);return this.settings&&(t.inTangents=this.settings.inTangents,t.outTangents=this.settings.outTangents),t}setInterpolation(e){let t;switch(e){case Ma:t=this.InterpolantFactoryMethodDiscrete;break;case Rc:t=this.InterpolantFactoryMethodLinear;break;case _c:t=this.InterpolantFactoryMethodSmooth;break;case Ef:t=this.InterpolantFactoryMethodBezier;break}if(t===void 0){let i="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(i);return je("KeyframeTrack:",i),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return Ma;case this.InterpolantFactoryMethodLinear:return Rc;case this.InterpolantFactoryMethodSmooth:return _c;case this.InterpolantFactoryMethodBezier:return Ef}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]+=e;pc(this.settings)&&(Yg(this.settings.inTangents,e),Yg(this.settings.outTangents,e))}return this}scale(e){if(e!==1){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]*=e;pc(this.settings)&&(Zg(this.settings.inTangents,e),Zg(this.settings.outTangents,e))}return this}trim(e,t){let i=this.times,s=i.length,r=0,o=s-1;for(;r!==s&&i[r]<e;)++r;for(;o!==-1&&i[o]>t;)--o;if(++o,r!==0||o!==s){r>=o&&(o=Math.max(o,1),r=o-1);let a=this.getValueSize();this.times=i.slice(r,o),this.values=this.values.slice(r*a,o*a)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(at("KeyframeTrack: Invalid value size in track.",this),e=!1);let i=this.times,s=this.values,r=i.length;r===0&&(at("KeyframeTrack: Track is empty.",this),e=!1);let o=null;for(let a=0;a!==r;a++){let l=i[a];if(typeof l=="number"&&isNaN(l)){at("KeyframeTrack: Time is not a valid number.",this,a,l),e=!1;break}if(o!==null&&o>l){at("KeyframeTrack: Out of order keys.",this,a,l,o),e=!1;break}o=l}if(s!==void 0&&bv(s))for(let a=0,l=s.length;a!==l;++a){let c=s[a];if(isNaN(c)){at("KeyframeTrack: Value is not a valid number.",this,a,c),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),i=this.getValueSize(),s=this.getInterpolation()===_c,r=e.length-1,o=1;for(let a=1;a<r;++a){let l=!1,c=e[a],h=e[a+1];if(c!==h&&(a!==1||c!==e[0]))if(s)l=!0;else{let f=a*i,u=f-i,m=f+i;for(let g=0;g!==i;++g){let v=t[f+g];if(v!==t[u+g]||v!==t[m+g]){l=!0;break}}}if(l){if(a!==o){e[o]=e[a];let f=a*i,u=o*i;for(let m=0;m!==i;++m)t[u+m]=t[f+m]}++o}}if(r>0){e[o]=e[r];for(let a=r*i,l=o*i,c=0;c!==i;++c)t[l+c]=t[a+c];++o}return o!==e.length?(this.times=e.slice(0,o),this.values=t.slice(0,o*i)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),i=this.constructor,s=new i(this.name,e,t);return s.createInterpolant=this.createInterpolant,pc(this.settings)&&(s.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),s}};function Yg(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]+=e}function Zg(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]*=e}yi.prototype.ValueTypeName="";yi.prototype.TimeBufferType=Float32Array;yi.prototype.ValueBufferType=Float32Array;yi.prototype.DefaultInterpolation=Rc;var ir=class extends yi{constructor(e,t,i){super(e,t,i)}};ir.prototype.ValueTypeName="bool";ir.prototype.ValueBufferType=Array;ir.prototype.DefaultInterpolation=Ma;ir.prototype.InterpolantFactoryMethodLinear=void 0;ir.prototype.InterpolantFactoryMethodSmooth=void 0;var Xc=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}};Xc.prototype.ValueTypeName="color";var $c=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}};$c.prototype.ValueTypeName="number";var qc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=(i-t)/(s-t),c=e*a;for(let h=c+a;c!==h;c+=4)gi.slerpFlat(r,0,o,c-a,o,c,l);return r}},ka=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}InterpolantFactoryMethodLinear(e){return new qc(this.times,this.values,this.getValueSize(),e)}};ka.prototype.ValueTypeName="quaternion";ka.prototype.InterpolantFactoryMethodSmooth=void 0;var sr=class extends yi{constructor(e,t,i){super(e,t,i)}};sr.prototype.ValueTypeName="string";sr.prototype.ValueBufferType=Array;sr.prototype.DefaultInterpolation=Ma;sr.prototype.InterpolantFactoryMethodLinear=void 0;sr.prototype.InterpolantFactoryMethodSmooth=void 0;var Yc=class extends yi{constructor(e,t,i,s){super(e,t,i,s)}};Yc.prototype.ValueTypeName="vector";var Zc=class{constructor(e,t,i){let s=this,r=!1,o=0,a=0,l,c=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=i,this._abortController=null,this.itemStart=function(h){a++,r===!1&&s.onStart!==void 0&&s.onStart(h,o,a),r=!0},this.itemEnd=function(h){o++,s.onProgress!==void 0&&s.onProgress(h,o,a),o===a&&(r=!1,s.onLoad!==void 0&&s.onLoad())},this.itemError=function(h){s.onError!==void 0&&s.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),l?l(h):h},this.setURLModifier=function(h){return l=h,this},this.addHandler=function(h,f){return c.push(h,f),this},this.removeHandler=function(h){let f=c.indexOf(h);return f!==-1&&c.splice(f,2),this},this.getHandler=function(h){for(let f=0,u=c.length;f<u;f+=2){let m=c[f],g=c[f+1];if(m.global&&(m.lastIndex=0),m.test(h))return g}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},z0=new Zc,Kc=class{constructor(e){this.manager=e!==void 0?e:z0,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(e,t){let i=this;return new Promise(function(s,r){i.load(e,s,t,r)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}setPriority(e){return this.priority=e,this}setCache(e){return this.cache=e,this}abort(){return this}};Kc.DEFAULT_MATERIAL_NAME="__DEFAULT";var mc=new J,gc=new gi,Qi=new J,za=class extends ei{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new tn,this.projectionMatrix=new tn,this.projectionMatrixInverse=new tn,this.coordinateSystem=Ti,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(mc,gc,Qi),Qi.x===1&&Qi.y===1&&Qi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(mc,gc,Qi.set(1,1,1)).invert()}updateWorldMatrix(e,t,i=!1){super.updateWorldMatrix(e,t,i),this.matrixWorld.decompose(mc,gc,Qi),Qi.x===1&&Qi.y===1&&Qi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(mc,gc,Qi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},Ks=new J,Kg=new pt,Jg=new pt,Yn=class extends za{constructor(e=50,t=1,i=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=i,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=Ao*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(ba*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Ao*2*Math.atan(Math.tan(ba*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,i){Ks.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(Ks.x,Ks.y).multiplyScalar(-e/Ks.z),Ks.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set(Ks.x,Ks.y).multiplyScalar(-e/Ks.z)}getViewSize(e,t){return this.getViewBounds(e,Kg,Jg),t.subVectors(Jg,Kg)}setViewOffset(e,t,i,s,r,o){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(ba*.5*this.fov)/this.zoom,i=2*t,s=this.aspect*i,r=-.5*s,o=this.view;if(this.view!==null&&this.view.enabled){let l=o.fullWidth,c=o.fullHeight;r+=o.offsetX*s/l,t-=o.offsetY*i/c,s*=o.width/l,i*=o.height/c}let a=this.filmOffset;a!==0&&(r+=e*a/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-i,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}};var Jc=class extends za{constructor(e=-1,t=1,i=1,s=-1,r=.1,o=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=i,this.bottom=s,this.near=r,this.far=o,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,i,s,r,o){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,s=(this.top+this.bottom)/2,r=i-e,o=i+e,a=s+t,l=s-t;if(this.view!==null&&this.view.enabled){let c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,o=r+c*this.view.width,a-=h*this.view.offsetY,l=a-h*this.view.height}this.projectionMatrix.makeOrthographic(r,o,a,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}};var So=-90,Mo=1,No=class extends ei{constructor(e,t,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;let s=new Yn(So,Mo,e,t);s.layers=this.layers,this.add(s);let r=new Yn(So,Mo,e,t);r.layers=this.layers,this.add(r);let o=new Yn(So,Mo,e,t);o.layers=this.layers,this.add(o);let a=new Yn(So,Mo,e,t);a.layers=this.layers,this.add(a);let l=new Yn(So,Mo,e,t);l.layers=this.layers,this.add(l);let c=new Yn(So,Mo,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[i,s,r,o,a,l]=t;for(let c of t)this.remove(c);if(e===Ti)i.up.set(0,1,0),i.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),o.up.set(0,0,1),o.lookAt(0,-1,0),a.up.set(0,1,0),a.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Ta)i.up.set(0,-1,0),i.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),o.up.set(0,0,-1),o.lookAt(0,-1,0),a.up.set(0,-1,0),a.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:i,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[r,o,a,l,c,h]=this.children,f=e.getRenderTarget(),u=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),g=e.xr.enabled;e.xr.enabled=!1;let v=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let d=!1;e.isWebGLRenderer===!0?d=e.state.buffers.depth.getReversed():d=e.reversedDepthBuffer,e.setRenderTarget(i,0,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(i,1,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(i,2,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(i,3,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(i,4,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),i.texture.mipmapsAutoUpdate=v,e.setRenderTarget(i,5,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(f,u,m),e.xr.enabled=g,i.texture.needsPMREMUpdate=!0}},jc=class extends Yn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}};var ud="\\[\\]\\.:\\/",ob=new RegExp("["+ud+"]","g"),fd="[^"+ud+"]",ab="[^"+ud.replace("\\.","")+"]",lb=/((?:WC+[\/:])*)/.source.replace("WC",fd),cb=/(WCOD+)?/.source.replace("WCOD",ab),hb=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",fd),ub=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",fd),fb=new RegExp("^"+lb+cb+hb+ub+"$"),db=["material","materials","bones","map"],If=class{constructor(e,t,i){let s=i||Qt.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,s)}getValue(e,t){this.bind();let i=this._targetGroup.nCachedObjects_,s=this._bindings[i];s!==void 0&&s.getValue(e,t)}setValue(e,t){let i=this._bindings;for(let s=this._targetGroup.nCachedObjects_,r=i.length;s!==r;++s)i[s].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].unbind()}},Qt=class n{constructor(e,t,i){this.path=t,this.parsedPath=i||n.parseTrackName(t),this.node=n.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,i){return e&&e.isAnimationObjectGroup?new n.Composite(e,t,i):new n(e,t,i)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(ob,"")}static parseTrackName(e){let t=fb.exec(e);if(t===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+e);let i={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},s=i.nodeName&&i.nodeName.lastIndexOf(".");if(s!==void 0&&s!==-1){let r=i.nodeName.substring(s+1);db.indexOf(r)!==-1&&(i.nodeName=i.nodeName.substring(0,s),i.objectName=r)}if(i.propertyName===null||i.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+e);return i}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let i=e.skeleton.getBoneByName(t);if(i!==void 0)return i}if(e.children){let i=function(r){for(let o=0;o<r.length;o++){let a=r[o];if(a.name===t||a.uuid===t)return a;let l=i(a.children);if(l)return l}return null},s=i(e.children);if(s)return s}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)e[t++]=i[s]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,i=t.objectName,s=t.propertyName,r=t.propertyIndex;if(e||(e=n.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){je("PropertyBinding: No target node found for track: "+this.path+".");return}if(i){let c=t.objectIndex;switch(i){case"materials":if(!e.material){at("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){at("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){at("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let h=0;h<e.length;h++)if(e[h].name===c){c=h;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){at("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){at("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[i]===void 0){at("PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[i]}if(c!==void 0){if(e[c]===void 0){at("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[c]}}let o=e[s];if(o===void 0){let c=t.nodeName;at("PropertyBinding: Trying to update property for track: "+c+"."+s+" but it wasn't found.",e);return}let a=this.Versioning.None;this.targetObject=e,e.isMaterial===!0?a=this.Versioning.NeedsUpdate:e.isObject3D===!0&&(a=this.Versioning.MatrixWorldNeedsUpdate);let l=this.BindingType.Direct;if(r!==void 0){if(s==="morphTargetInfluences"){if(!e.geometry){at("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){at("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[r]!==void 0&&(r=e.morphTargetDictionary[r])}l=this.BindingType.ArrayElement,this.resolvedProperty=o,this.propertyIndex=r}else o.fromArray!==void 0&&o.toArray!==void 0?(l=this.BindingType.HasFromToArray,this.resolvedProperty=o):Array.isArray(o)?(l=this.BindingType.EntireArray,this.resolvedProperty=o):this.propertyName=s;this.getValue=this.GetterByBindingType[l],this.setValue=this.SetterByBindingTypeAndVersioning[l][a]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};Qt.Composite=If;Qt.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};Qt.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};Qt.prototype.GetterByBindingType=[Qt.prototype._getValue_direct,Qt.prototype._getValue_array,Qt.prototype._getValue_arrayElement,Qt.prototype._getValue_toArray];Qt.prototype.SetterByBindingTypeAndVersioning=[[Qt.prototype._setValue_direct,Qt.prototype._setValue_direct_setNeedsUpdate,Qt.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[Qt.prototype._setValue_array,Qt.prototype._setValue_array_setNeedsUpdate,Qt.prototype._setValue_array_setMatrixWorldNeedsUpdate],[Qt.prototype._setValue_arrayElement,Qt.prototype._setValue_arrayElement_setNeedsUpdate,Qt.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[Qt.prototype._setValue_fromArray,Qt.prototype._setValue_fromArray_setNeedsUpdate,Qt.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var eR=new Float32Array(1);var Do=class{constructor(e=1,t=0,i=0){this.radius=e,this.phi=t,this.theta=i}set(e,t,i){return this.radius=e,this.phi=t,this.theta=i,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=bt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,i){return this.radius=Math.sqrt(e*e+t*t+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,i),this.phi=Math.acos(bt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var yd=class yd{constructor(e,t,i,s){this.elements=[1,0,0,1],e!==void 0&&this.set(e,t,i,s)}identity(){return this.set(1,0,0,1),this}fromArray(e,t=0){for(let i=0;i<4;i++)this.elements[i]=e[i+t];return this}set(e,t,i,s){let r=this.elements;return r[0]=e,r[2]=t,r[1]=i,r[3]=s,this}};yd.prototype.isMatrix2=!0;var Pf=yd;var Ga=class extends Na{constructor(e=10,t=10,i=4473924,s=8947848){i=new _t(i),s=new _t(s);let r=t/2,o=e/t,a=e/2,l=[],c=[];for(let u=0,m=0,g=-a;u<=t;u++,g+=o){l.push(-a,0,g,a,0,g),l.push(g,0,-a,g,0,a);let v=u===r?i:s;v.toArray(c,m),m+=3,v.toArray(c,m),m+=3,v.toArray(c,m),m+=3,v.toArray(c,m),m+=3}let h=new ti;h.setAttribute("position",new Nn(l,3)),h.setAttribute("color",new Nn(c,3));let f=new Io({vertexColors:!0,toneMapped:!1});super(h,f),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Ha=class extends Na{constructor(e=1){let t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],i=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new ti;s.setAttribute("position",new Nn(t,3)),s.setAttribute("color",new Nn(i,3));let r=new Io({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,i){let s=new _t,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(i),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Va=class extends Fi{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function dd(n,e,t,i){let s=pb(i);switch(t){case Jf:return n*e;case Qf:return n*e/s.components*s.byteLength;case oh:return n*e/s.components*s.byteLength;case lr:return n*e*2/s.components*s.byteLength;case ah:return n*e*2/s.components*s.byteLength;case jf:return n*e*3/s.components*s.byteLength;case Gi:return n*e*4/s.components*s.byteLength;case lh:return n*e*4/s.components*s.byteLength;case $a:case qa:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Ya:case Za:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case hh:case fh:return Math.max(n,16)*Math.max(e,8)/4;case ch:case uh:return Math.max(n,8)*Math.max(e,8)/2;case dh:case ph:case gh:case _h:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case mh:case Ka:case yh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case xh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case vh:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case bh:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case Sh:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case Mh:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case wh:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case Eh:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case Th:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case Ah:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case Rh:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case Ch:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case Ih:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case Ph:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case Lh:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case Nh:case Dh:case Uh:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Oh:case Fh:return Math.ceil(n/4)*Math.ceil(e/4)*8;case Ja:case Bh:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function pb(n){switch(n){case xi:case qf:return{byteLength:1,components:1};case Bo:case Yf:case zi:return{byteLength:2,components:1};case sh:case rh:return{byteLength:2,components:4};case Bi:case ih:case ki:return{byteLength:4,components:1};case Zf:case Kf:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?je("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187");function l_(){let n=null,e=!1,t=null,i=null;function s(r,o){i=n.requestAnimationFrame(s),t(r,o)}return{start:function(){e!==!0&&t!==null&&n!==null&&(i=n.requestAnimationFrame(s),e=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){n=r}}}function gb(n){let e=new WeakMap;function t(a,l){let c=a.array,h=a.usage,f=c.byteLength,u=n.createBuffer();n.bindBuffer(l,u),n.bufferData(l,c,h),a.onUploadCallback();let m;if(c instanceof Float32Array)m=n.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=n.HALF_FLOAT;else if(c instanceof Uint16Array)a.isFloat16BufferAttribute?m=n.HALF_FLOAT:m=n.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=n.SHORT;else if(c instanceof Uint32Array)m=n.UNSIGNED_INT;else if(c instanceof Int32Array)m=n.INT;else if(c instanceof Int8Array)m=n.BYTE;else if(c instanceof Uint8Array)m=n.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:u,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:a.version,size:f}}function i(a,l,c){let h=l.array,f=l.updateRanges;if(n.bindBuffer(c,a),f.length===0)n.bufferSubData(c,0,h);else{f.sort((m,g)=>m.start-g.start);let u=0;for(let m=1;m<f.length;m++){let g=f[u],v=f[m];v.start<=g.start+g.count+1?g.count=Math.max(g.count,v.start+v.count-g.start):(++u,f[u]=v)}f.length=u+1;for(let m=0,g=f.length;m<g;m++){let v=f[m];n.bufferSubData(c,v.start*h.BYTES_PER_ELEMENT,h,v.start,v.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(a){return a.isInterleavedBufferAttribute&&(a=a.data),e.get(a)}function r(a){a.isInterleavedBufferAttribute&&(a=a.data);let l=e.get(a);l&&(n.deleteBuffer(l.buffer),e.delete(a))}function o(a,l){if(a.isInterleavedBufferAttribute&&(a=a.data),a.isGLBufferAttribute){let h=e.get(a);(!h||h.version<a.version)&&e.set(a,{buffer:a.buffer,type:a.type,bytesPerElement:a.elementSize,version:a.version});return}let c=e.get(a);if(c===void 0)e.set(a,t(a,l));else if(c.version<a.version){if(c.size!==a.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(c.buffer,a,l),c.version=a.version}}return{get:s,remove:r,update:o}}var _b=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,yb=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,xb=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,vb=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,bb=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,Sb=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,Mb=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,wb=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,Eb=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,Tb=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Ab=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,Rb=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,Cb=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,Ib=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,Pb=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,Lb=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,Nb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,Db=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,Ub=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,Ob=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,Fb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,Bb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,kb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,zb=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,Gb=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,Hb=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,Vb=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,Wb=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,Xb=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,$b="gl_FragColor = linearToOutputTexel( gl_FragColor );",qb=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,Yb=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,Zb=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,Kb=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,Jb=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,jb=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,Qb=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,eS=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,tS=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,nS=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,iS=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,sS=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,rS=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,oS=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,aS=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,lS=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,cS=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,hS=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,uS=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,fS=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,dS=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,pS=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,mS=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,gS=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,_S=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,yS=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,xS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,vS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,bS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,SS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,MS=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,wS=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,ES=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,TS=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,AS=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,RS=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,CS=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,IS=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,PS=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,LS=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,NS=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,DS=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,US=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,OS=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,FS=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,BS=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,kS=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,zS=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,GS=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,HS=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,VS=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,WS=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,XS=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,$S=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,qS=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,YS=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,ZS=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,KS=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,JS=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,jS=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,QS=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,eM=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,tM=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,nM=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,iM=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,sM=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,rM=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,oM=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,aM=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,lM=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,cM=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,hM=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,uM=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,fM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,dM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,pM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,mM=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,gM=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,_M=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,yM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,xM=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,vM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,bM=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,SM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,MM=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,wM=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,EM=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,TM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,AM=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,RM=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,CM=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,IM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,PM=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,LM=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,NM=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,DM=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,UM=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,OM=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,FM=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,BM=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,kM=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,zM=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,GM=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,HM=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,VM=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,WM=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,XM=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,$M=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,qM=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,YM=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,ZM=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,yt={alphahash_fragment:_b,alphahash_pars_fragment:yb,alphamap_fragment:xb,alphamap_pars_fragment:vb,alphatest_fragment:bb,alphatest_pars_fragment:Sb,aomap_fragment:Mb,aomap_pars_fragment:wb,batching_pars_vertex:Eb,batching_vertex:Tb,begin_vertex:Ab,beginnormal_vertex:Rb,bsdfs:Cb,iridescence_fragment:Ib,bumpmap_pars_fragment:Pb,clipping_planes_fragment:Lb,clipping_planes_pars_fragment:Nb,clipping_planes_pars_vertex:Db,clipping_planes_vertex:Ub,color_fragment:Ob,color_pars_fragment:Fb,color_pars_vertex:Bb,color_vertex:kb,common:zb,defaultnormal_vertex:Gb,displacementmap_pars_vertex:Hb,displacementmap_vertex:Vb,emissivemap_fragment:Wb,emissivemap_pars_fragment:Xb,colorspace_fragment:$b,colorspace_pars_fragment:qb,envmap_fragment:Yb,envmap_common_pars_fragment:Zb,envmap_pars_fragment:Kb,envmap_pars_vertex:Jb,envmap_physical_pars_fragment:lS,envmap_vertex:jb,fog_vertex:Qb,fog_pars_vertex:eS,fog_fragment:tS,fog_pars_fragment:nS,gradientmap_pars_fragment:iS,lightmap_pars_fragment:sS,lights_lambert_fragment:rS,lights_lambert_pars_fragment:oS,lights_pars_begin:aS,lights_toon_fragment:cS,lights_toon_pars_fragment:hS,lights_phong_fragment:uS,lights_phong_pars_fragment:fS,lights_physical_fragment:dS,lights_physical_pars_fragment:pS,lights_fragment_begin:mS,lights_fragment_maps:gS,lights_fragment_end:_S,lightprobes_pars_fragment:yS,logdepthbuf_fragment:xS,logdepthbuf_pars_fragment:vS,logdepthbuf_pars_vertex:bS,logdepthbuf_vertex:SS,map_fragment:MS,map_pars_fragment:wS,map_particle_fragment:ES,map_particle_pars_fragment:TS,metalnessmap_fragment:AS,metalnessmap_pars_fragment:RS,morphinstance_vertex:CS,morphcolor_vertex:IS,morphnormal_vertex:PS,morphtarget_pars_vertex:LS,morphtarget_vertex:NS,normal_fragment_begin:DS,normal_fragment_maps:US,normal_pars_fragment:OS,normal_pars_vertex:FS,normal_vertex:BS,normalmap_pars_fragment:kS,clearcoat_normal_fragment_begin:zS,clearcoat_normal_fragment_maps:GS,clearcoat_pars_fragment:HS,iridescence_pars_fragment:VS,opaque_fragment:WS,packing:XS,premultiplied_alpha_fragment:$S,project_vertex:qS,dithering_fragment:YS,dithering_pars_fragment:ZS,roughnessmap_fragment:KS,roughnessmap_pars_fragment:JS,shadowmap_pars_fragment:jS,shadowmap_pars_vertex:QS,shadowmap_vertex:eM,shadowmask_pars_fragment:tM,skinbase_vertex:nM,skinning_pars_vertex:iM,skinning_vertex:sM,skinnormal_vertex:rM,specularmap_fragment:oM,specularmap_pars_fragment:aM,tonemapping_fragment:lM,tonemapping_pars_fragment:cM,transmission_fragment:hM,transmission_pars_fragment:uM,uv_pars_fragment:fM,uv_pars_vertex:dM,uv_vertex:pM,worldpos_vertex:mM,background_vert:gM,background_frag:_M,backgroundCube_vert:yM,backgroundCube_frag:xM,cube_vert:vM,cube_frag:bM,depth_vert:SM,depth_frag:MM,distance_vert:wM,distance_frag:EM,equirect_vert:TM,equirect_frag:AM,linedashed_vert:RM,linedashed_frag:CM,meshbasic_vert:IM,meshbasic_frag:PM,meshlambert_vert:LM,meshlambert_frag:NM,meshmatcap_vert:DM,meshmatcap_frag:UM,meshnormal_vert:OM,meshnormal_frag:FM,meshphong_vert:BM,meshphong_frag:kM,meshphysical_vert:zM,meshphysical_frag:GM,meshtoon_vert:HM,meshtoon_frag:VM,points_vert:WM,points_frag:XM,shadow_vert:$M,shadow_frag:qM,sprite_vert:YM,sprite_frag:ZM},Ue={common:{diffuse:{value:new _t(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new lt},alphaMap:{value:null},alphaMapTransform:{value:new lt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new lt}},envmap:{envMap:{value:null},envMapRotation:{value:new lt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new lt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new lt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new lt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new lt},normalScale:{value:new pt(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new lt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new lt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new lt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new lt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new _t(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new _t(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new lt},alphaTest:{value:0},uvTransform:{value:new lt}},sprite:{diffuse:{value:new _t(16777215)},opacity:{value:1},center:{value:new pt(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new lt},alphaMap:{value:null},alphaMapTransform:{value:new lt},alphaTest:{value:0}}},os={basic:{uniforms:Gn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.fog]),vertexShader:yt.meshbasic_vert,fragmentShader:yt.meshbasic_frag},lambert:{uniforms:Gn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new _t(0)},envMapIntensity:{value:1}}]),vertexShader:yt.meshlambert_vert,fragmentShader:yt.meshlambert_frag},phong:{uniforms:Gn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new _t(0)},specular:{value:new _t(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:yt.meshphong_vert,fragmentShader:yt.meshphong_frag},standard:{uniforms:Gn([Ue.common,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.roughnessmap,Ue.metalnessmap,Ue.fog,Ue.lights,{emissive:{value:new _t(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:yt.meshphysical_vert,fragmentShader:yt.meshphysical_frag},toon:{uniforms:Gn([Ue.common,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.gradientmap,Ue.fog,Ue.lights,{emissive:{value:new _t(0)}}]),vertexShader:yt.meshtoon_vert,fragmentShader:yt.meshtoon_frag},matcap:{uniforms:Gn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,{matcap:{value:null}}]),vertexShader:yt.meshmatcap_vert,fragmentShader:yt.meshmatcap_frag},points:{uniforms:Gn([Ue.points,Ue.fog]),vertexShader:yt.points_vert,fragmentShader:yt.points_frag},dashed:{uniforms:Gn([Ue.common,Ue.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:yt.linedashed_vert,fragmentShader:yt.linedashed_frag},depth:{uniforms:Gn([Ue.common,Ue.displacementmap]),vertexShader:yt.depth_vert,fragmentShader:yt.depth_frag},normal:{uniforms:Gn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,{opacity:{value:1}}]),vertexShader:yt.meshnormal_vert,fragmentShader:yt.meshnormal_frag},sprite:{uniforms:Gn([Ue.sprite,Ue.fog]),vertexShader:yt.sprite_vert,fragmentShader:yt.sprite_frag},background:{uniforms:{uvTransform:{value:new lt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:yt.background_vert,fragmentShader:yt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new lt}},vertexShader:yt.backgroundCube_vert,fragmentShader:yt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:yt.cube_vert,fragmentShader:yt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:yt.equirect_vert,fragmentShader:yt.equirect_frag},distance:{uniforms:Gn([Ue.common,Ue.displacementmap,{referencePosition:{value:new J},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:yt.distance_vert,fragmentShader:yt.distance_frag},shadow:{uniforms:Gn([Ue.lights,Ue.fog,{color:{value:new _t(0)},opacity:{value:1}}]),vertexShader:yt.shadow_vert,fragmentShader:yt.shadow_frag}};os.physical={uniforms:Gn([os.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new lt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new lt},clearcoatNormalScale:{value:new pt(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new lt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new lt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new lt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new lt},sheen:{value:0},sheenColor:{value:new _t(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new lt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new lt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new lt},transmissionSamplerSize:{value:new pt},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new lt},attenuationDistance:{value:0},attenuationColor:{value:new _t(0)},specularColor:{value:new _t(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new lt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new lt},anisotropyVector:{value:new pt},anisotropyMap:{value:null},anisotropyMapTransform:{value:new lt}}]),vertexShader:yt.meshphysical_vert,fragmentShader:yt.meshphysical_frag};var kh={r:0,b:0,g:0},KM=new tn,c_=new lt;c_.set(-1,0,0,0,1,0,0,0,1);function JM(n,e,t,i,s,r){let o=new _t(0),a=s===!0?0:1,l,c,h=null,f=0,u=null;function m(x){let A=x.isScene===!0?x.background:null;if(A&&A.isTexture){let S=x.backgroundBlurriness>0;A=e.get(A,S)}return A}function g(x){let A=!1,S=m(x);S===null?d(o,a):S&&S.isColor&&(d(S,1),A=!0);let C=n.xr.getEnvironmentBlendMode();C==="additive"?t.buffers.color.setClear(0,0,0,1,r):C==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(n.autoClear||A)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function v(x,A){let S=m(A);S&&S.isCubeTexture?(c===void 0&&(c=new ts(new Lo(1,1,1),new ns({name:"BackgroundCubeMaterial",uniforms:Ur(os.backgroundCube.uniforms),vertexShader:os.backgroundCube.vertexShader,fragmentShader:os.backgroundCube.fragmentShader,side:Kn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(C,T,_){this.matrixWorld.copyPosition(_.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(c)),c.material.uniforms.envMap.value=S,c.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(KM.makeRotationFromEuler(A.backgroundRotation)).transpose(),S.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(c_),c.material.toneMapped=At.getTransfer(S.colorSpace)!==Ft,(h!==S||f!==S.version||u!==n.toneMapping)&&(c.material.needsUpdate=!0,h=S,f=S.version,u=n.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):S&&S.isTexture&&(l===void 0&&(l=new ts(new Ba(2,2),new ns({name:"BackgroundMaterial",uniforms:Ur(os.background.uniforms),vertexShader:os.background.vertexShader,fragmentShader:os.background.fragmentShader,side:ar,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(l)),l.material.uniforms.t2D.value=S,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.toneMapped=At.getTransfer(S.colorSpace)!==Ft,S.matrixAutoUpdate===!0&&S.updateMatrix(),l.material.uniforms.uvTransform.value.copy(S.matrix),(h!==S||f!==S.version||u!==n.toneMapping)&&(l.material.needsUpdate=!0,h=S,f=S.version,u=n.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function d(x,A){x.getRGB(kh,hd(n)),t.buffers.color.setClear(kh.r,kh.g,kh.b,A,r)}function p(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return o},setClearColor:function(x,A=1){o.set(x),a=A,d(o,a)},getClearAlpha:function(){return a},setClearAlpha:function(x){a=x,d(o,a)},render:g,addToRenderList:v,dispose:p}}function jM(n,e){let t=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},s=u(null),r=s,o=!1;function a(R,G,B,L,z){let q=!1,O=f(R,L,B,G);r!==O&&(r=O,c(r.object)),q=m(R,L,B,z),q&&g(R,L,B,z),z!==null&&e.update(z,n.ELEMENT_ARRAY_BUFFER),(q||o)&&(o=!1,S(R,G,B,L),z!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(z).buffer))}function l(){return n.createVertexArray()}function c(R){return n.bindVertexArray(R)}function h(R){return n.deleteVertexArray(R)}function f(R,G,B,L){let z=L.wireframe===!0,q=i[G.id];q===void 0&&(q={},i[G.id]=q);let O=R.isInstancedMesh===!0?R.id:0,re=q[O];re===void 0&&(re={},q[O]=re);let X=re[B.id];X===void 0&&(X={},re[B.id]=X);let $=X[z];return $===void 0&&($=u(l()),X[z]=$),$}function u(R){let G=[],B=[],L=[];for(let z=0;z<t;z++)G[z]=0,B[z]=0,L[z]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:G,enabledAttributes:B,attributeDivisors:L,object:R,attributes:{},index:null}}function m(R,G,B,L){let z=r.attributes,q=G.attributes,O=0,re=B.getAttributes();for(let X in re)if(re[X].location>=0){let W=z[X],ne=q[X];if(ne===void 0&&(X==="instanceMatrix"&&R.instanceMatrix&&(ne=R.instanceMatrix),X==="instanceColor"&&R.instanceColor&&(ne=R.instanceColor)),W===void 0||W.attribute!==ne||ne&&W.data!==ne.data)return!0;O++}return r.attributesNum!==O||r.index!==L}function g(R,G,B,L){let z={},q=G.attributes,O=0,re=B.getAttributes();for(let X in re)if(re[X].location>=0){let W=q[X];W===void 0&&(X==="instanceMatrix"&&R.instanceMatrix&&(W=R.instanceMatrix),X==="instanceColor"&&R.instanceColor&&(W=R.instanceColor));let ne={};ne.attribute=W,W&&W.data&&(ne.data=W.data),z[X]=ne,O++}r.attributes=z,r.attributesNum=O,r.index=L}function v(){let R=r.newAttributes;for(let G=0,B=R.length;G<B;G++)R[G]=0}function d(R){p(R,0)}function p(R,G){let B=r.newAttributes,L=r.enabledAttributes,z=r.attributeDivisors;B[R]=1,L[R]===0&&(n.enableVertexAttribArray(R),L[R]=1),z[R]!==G&&(n.vertexAttribDivisor(R,G),z[R]=G)}function x(){let R=r.newAttributes,G=r.enabledAttributes;for(let B=0,L=G.length;B<L;B++)G[B]!==R[B]&&(n.disableVertexAttribArray(B),G[B]=0)}function A(R,G,B,L,z,q,O){O===!0?n.vertexAttribIPointer(R,G,B,z,q):n.vertexAttribPointer(R,G,B,L,z,q)}function S(R,G,B,L){v();let z=L.attributes,q=B.getAttributes(),O=G.defaultAttributeValues;for(let re in q){let X=q[re];if(X.location>=0){let $=z[re];if($===void 0&&(re==="instanceMatrix"&&R.instanceMatrix&&($=R.instanceMatrix),re==="instanceColor"&&R.instanceColor&&($=R.instanceColor)),$!==void 0){let W=$.normalized,ne=$.itemSize,le=e.get($);if(le===void 0)continue;let Q=le.buffer,me=le.type,pe=le.bytesPerElement,be=me===n.INT||me===n.UNSIGNED_INT||$.gpuType===ih;if($.isInterleavedBufferAttribute){let xe=$.data,We=xe.isInterleavedBuffer===!0?xe.stride:xe.itemSize,Qe=$.offset;if(xe.isInstancedInterleavedBuffer||xe.isInstancedBufferAttribute){for(let Ne=0;Ne<X.locationSize;Ne++)p(X.location+Ne,xe.meshPerAttribute);R.isInstancedMesh!==!0&&L._maxInstanceCount===void 0&&(L._maxInstanceCount=xe.meshPerAttribute*xe.count)}else for(let Ne=0;Ne<X.locationSize;Ne++)d(X.location+Ne);n.bindBuffer(n.ARRAY_BUFFER,Q);for(let Ne=0;Ne<X.locationSize;Ne++)A(X.location+Ne,ne/X.locationSize,me,W,We*pe,(Qe+ne/X.locationSize*Ne)*pe,be)}else{if($.isInstancedBufferAttribute){for(let xe=0;xe<X.locationSize;xe++)p(X.location+xe,$.meshPerAttribute);R.isInstancedMesh!==!0&&L._maxInstanceCount===void 0&&(L._maxInstanceCount=$.meshPerAttribute*$.count)}else for(let xe=0;xe<X.locationSize;xe++)d(X.location+xe);n.bindBuffer(n.ARRAY_BUFFER,Q);for(let xe=0;xe<X.locationSize;xe++)A(X.location+xe,ne/X.locationSize,me,W,ne*pe,ne/X.locationSize*xe*pe,be)}}else if(O!==void 0){let W=O[re];if(W!==void 0)switch(W.length){case 2:n.vertexAttrib2fv(X.location,W);break;case 3:n.vertexAttrib3fv(X.location,W);break;case 4:n.vertexAttrib4fv(X.location,W);break;default:n.vertexAttrib1fv(X.location,W)}}}}x()}function C(){U();for(let R in i){let G=i[R];for(let B in G){let L=G[B];for(let z in L){let q=L[z];for(let O in q)h(q[O].object),delete q[O];delete L[z]}}delete i[R]}}function T(R){if(i[R.id]===void 0)return;let G=i[R.id];for(let B in G){let L=G[B];for(let z in L){let q=L[z];for(let O in q)h(q[O].object),delete q[O];delete L[z]}}delete i[R.id]}function _(R){for(let G in i){let B=i[G];for(let L in B){let z=B[L];if(z[R.id]===void 0)continue;let q=z[R.id];for(let O in q)h(q[O].object),delete q[O];delete z[R.id]}}}function w(R){for(let G in i){let B=i[G],L=R.isInstancedMesh===!0?R.id:0,z=B[L];if(z!==void 0){for(let q in z){let O=z[q];for(let re in O)h(O[re].object),delete O[re];delete z[q]}delete B[L],Object.keys(B).length===0&&delete i[G]}}}function U(){N(),o=!0,r!==s&&(r=s,c(r.object))}function N(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:a,reset:U,resetDefaultState:N,dispose:C,releaseStatesOfGeometry:T,releaseStatesOfObject:w,releaseStatesOfProgram:_,initAttributes:v,enableAttribute:d,disableUnusedAttributes:x}}function QM(n,e,t){let i;function s(l){i=l}function r(l,c){n.drawArrays(i,l,c),t.update(c,i,1)}function o(l,c,h){h!==0&&(n.drawArraysInstanced(i,l,c,h),t.update(c,i,h))}function a(l,c,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,l,0,c,0,h);let u=0;for(let m=0;m<h;m++)u+=c[m];t.update(u,i,1)}this.setMode=s,this.render=r,this.renderInstances=o,this.renderMultiDraw=a}function ew(n,e,t,i){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){let _=e.get("EXT_texture_filter_anisotropic");s=n.getParameter(_.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function o(_){return!(_!==Gi&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function a(_){let w=_===zi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(_!==xi&&_!==ki&&!w&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function l(_){if(_==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";_="mediump"}return _==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp",h=l(c);h!==c&&(je("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);let f=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),u=t.logarithmicDepthBuffer===!0&&f===!1;t.reversedDepthBuffer===!0&&f===!1&&je("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&f===!0&&je("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let m=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),g=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),v=n.getParameter(n.MAX_TEXTURE_SIZE),d=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),p=n.getParameter(n.MAX_VERTEX_ATTRIBS),x=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),A=n.getParameter(n.MAX_VARYING_VECTORS),S=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),C=n.getParameter(n.MAX_SAMPLES),T=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:o,textureTypeReadable:a,precision:c,logarithmicDepthBuffer:u,reversedDepthBuffer:f,maxTextures:m,maxVertexTextures:g,maxTextureSize:v,maxCubemapSize:d,maxAttributes:p,maxVertexUniforms:x,maxVaryings:A,maxFragmentUniforms:S,maxSamples:C,samples:T}}function tw(n){let e=this,t=null,i=0,s=!1,r=!1,o=new pi,a=new lt,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(f,u){let m=f.length!==0||u||i!==0||s;return s=u,i=f.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(f,u){t=h(f,u,0)},this.setState=function(f,u,m){let g=f.clippingPlanes,v=f.clipIntersection,d=f.clipShadows,p=n.get(f);if(!s||g===null||g.length===0||r&&!d)r?h(null):c();else{let x=r?0:i,A=x*4,S=p.clippingState||null;l.value=S,S=h(g,u,A,m);for(let C=0;C!==A;++C)S[C]=t[C];p.clippingState=S,this.numIntersection=v?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=i>0),e.numPlanes=i,e.numIntersection=0}function h(f,u,m,g){let v=f!==null?f.length:0,d=null;if(v!==0){if(d=l.value,g!==!0||d===null){let p=m+v*4,x=u.matrixWorldInverse;a.getNormalMatrix(x),(d===null||d.length<p)&&(d=new Float32Array(p));for(let A=0,S=m;A!==v;++A,S+=4)o.copy(f[A]).applyMatrix4(x,a),o.normal.toArray(d,S),d[S+3]=o.constant}l.value=d,l.needsUpdate=!0}return e.numPlanes=v,e.numIntersection=0,d}}var el=class extends _i{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let i={width:e,height:e,depth:1},s=[i,i,i,i,i,i];this.texture=new Ua(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new Lo(5,5,5),r=new ns({name:"CubemapFromEquirect",uniforms:Ur(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:Kn,blending:Pr});r.uniforms.tEquirect.value=t;let o=new ts(s,r),a=t.minFilter;return t.minFilter===Ts&&(t.minFilter=Zn),new No(1,10,this).update(e,o),t.minFilter=a,o.geometry.dispose(),o.material.dispose(),this}clear(e,t=!0,i=!0,s=!0){let r=e.getRenderTarget();for(let o=0;o<6;o++)e.setRenderTarget(this,o),e.clear(t,i,s);e.setRenderTarget(r)}},G0=256,nw=3,iw=20,h_=256,u_=16,sw=3,rw=new J,ow=new _t,Gh=class n{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new No(1,10,null),this._boxMesh=new ts(new Lo(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,i=.1,s=100,r={}){let{size:o=256,position:a=rw}=r,l=this._renderer;this._setSize(o);let c=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);let f=l.autoClear,u=l.autoClearColor,m=l.autoClearDepth,g=l.autoClearStencil,v=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,v===null&&(e.background=l.getClearColor(ow));let d=new No(i,s,h);return d.position.copy(a),d.update(l,e),l.autoClear=f,l.autoClearColor=u,l.autoClearDepth=m,l.autoClearStencil=g,e.background=v,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=W0(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=V0(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(G0,ad(e))}_fromTexture(e,t){e.mapping===Nr||e.mapping===Fo?this._setSize(e.image.length===0?G0:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);let i=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(i),i}_allocateTarget(){let e=this._cubeSize,t=H0(e,!1,!1),i=Math.log2(e)-nw;for(let s=0;s<=i;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){let t=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==t||e&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=H0(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,i){let s=this._boxMesh,r=this._cubeCamera;s.material=i,r.renderTarget=e,r.activeMipmapLevel=t;let o=e.width>>t;e.viewport.set(0,0,o,o),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Nr||e.mapping===Fo?(this._cubemapMaterial===null&&(this._cubemapMaterial=W0()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=V0()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=aw(),this._integrationMaterial=lw());let t=this._cubeSize,i=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;let r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/u_);for(let o=0;o<=i;o++){let a=n.lodToRoughness(o,i);if(o>i-sw)r.roughness.value=a,this._renderCube(e,o,this._integrationMaterial);else{let l=a>0?Math.log2(t)+.5*Math.log2(6/(h_*Math.pow(a,4)))+.5:0;s.roughness.value=a,s.lodBias.value=l,this._renderCube(e,o,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=cw());let i=this._blurMaterial,s=i.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,i),s.envMap.value=e.texture,this._renderCube(r,0,i)}};function H0(n,e,t){return new el(n,{minFilter:Ts,generateMipmaps:e,type:zi,colorSpace:wa,depthBuffer:t})}function tl(n,e,t){return new ns({name:n,uniforms:e,vertexShader:yt.cube_vert,fragmentShader:t,side:Kn,blending:Pr,depthTest:!1,depthWrite:!1})}function aw(){return tl("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${h_}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function lw(){return tl("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:u_}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function cw(){return tl("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${iw}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function V0(){return tl("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function W0(){return tl("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function hw(n){let e=new WeakMap,t=new WeakMap,i=null;function s(u,m=!1){return u==null?null:m?o(u):r(u)}function r(u){if(u&&u.isTexture){let m=u.mapping;if(m===eh||m===th)if(e.has(u)){let g=e.get(u).texture;return a(g,u.mapping)}else{let g=u.image;if(g&&g.height>0){let v=new el(g.height);return v.fromEquirectangularTexture(n,u),e.set(u,v),u.addEventListener("dispose",c),a(v.texture,u.mapping)}else return null}}return u}function o(u){if(u&&u.isTexture&&u.isPMREMTexture!==!0){let m=u.mapping,g=m===eh||m===th,v=m===Nr||m===Fo;if(g||v){let d=t.get(u),p=d!==void 0?d.texture.pmremVersion:0;if(u.isRenderTargetTexture&&u.pmremVersion!==p)return i===null&&(i=new Gh(n)),d=g?i.fromEquirectangular(u,d):i.fromCubemap(u,d),d.texture.pmremVersion=u.pmremVersion,t.set(u,d),d.texture;if(d!==void 0)return d.texture;{let x=u.image;return g&&x&&x.height>0||v&&x&&l(x)?(i===null&&(i=new Gh(n)),d=g?i.fromEquirectangular(u):i.fromCubemap(u),d.texture.pmremVersion=u.pmremVersion,t.set(u,d),u.addEventListener("dispose",h),d.texture):null}}}return u}function a(u,m){return m===eh?u.mapping=Nr:m===th&&(u.mapping=Fo),u}function l(u){let m=0,g=6;for(let v=0;v<g;v++)u[v]!==void 0&&m++;return m===g}function c(u){let m=u.target;m.removeEventListener("dispose",c);let g=e.get(m);g!==void 0&&(e.delete(m),g.dispose())}function h(u){let m=u.target;m.removeEventListener("dispose",h);let g=t.get(m);g!==void 0&&(t.delete(m),g.dispose())}function f(){e=new WeakMap,t=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:s,dispose:f}}function uw(n){let e={};function t(i){if(e[i]!==void 0)return e[i];let s=n.getExtension(i);return e[i]=s,s}return{has:function(i){return t(i)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(i){let s=t(i);return s===null&&va("WebGLRenderer: "+i+" extension not supported."),s}}}function fw(n,e,t,i){let s={},r=new WeakMap,o=new FinalizationRegistry(g=>delete s[g]);function a(g){l(g.target)}function l(g){g.index!==null&&e.remove(g.index);for(let d in g.attributes)e.remove(g.attributes[d]);g.removeEventListener("dispose",a),delete s[g.id],o.unregister(g);let v=r.get(g);v&&(e.remove(v),r.delete(g)),i.releaseStatesOfGeometry(g),g.isInstancedBufferGeometry===!0&&delete g._maxInstanceCount,t.memory.geometries--}function c(g,v){return s[v.id]!==void 0||(v.addEventListener("dispose",a),s[v.id]=new WeakRef(v),o.register(v,v.id,v),t.memory.geometries++),v}function h(g){let v=g.attributes;for(let d in v)e.update(v[d],n.ARRAY_BUFFER)}function f(g){let v=g.index,d=g.attributes.position,p=0;if(d===void 0)return;let x=v!==null?v.array.length:d.array.length/3-1,A=d.count>=65535?La:Pa,S=new A(Math.ceil(x/3)*6,1),C=S.array;if(v!==null){let _=v.array;p=v.version;for(let w=0,U=0;w<x;w+=3){let N=_[w+0],R=_[w+1],G=_[w+2];C[U++]=N,C[U++]=R,C[U++]=R,C[U++]=G,C[U++]=G,C[U++]=N}}else{p=d.version;for(let _=0,w=0;_<x;_+=3){let U=_+0,N=_+1,R=_+2;C[w++]=U,C[w++]=N,C[w++]=N,C[w++]=R,C[w++]=R,C[w++]=U}}S.version=p;let T=r.get(g);T&&e.remove(T),r.set(g,S)}function u(g){let v=r.get(g);if(v){let d=g.index;d!==null&&v.version<d.version&&f(g)}else f(g);return r.get(g)}function m(){for(let g in s){let v=s[g].deref();v!==void 0&&l(v)}}return{get:c,update:h,getWireframeAttribute:u,dispose:m}}function dw(n,e,t){let i;function s(f){i=f}let r,o;function a(f){r=f.type,o=f.bytesPerElement}function l(f,u){n.drawElements(i,u,r,f*o),t.update(u,i,1)}function c(f,u,m){m!==0&&(n.drawElementsInstanced(i,u,r,f*o,m),t.update(u,i,m))}function h(f,u,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,u,0,r,f,0,m);let v=0;for(let d=0;d<m;d++)v+=u[d];t.update(v,i,1)}this.setMode=s,this.setIndex=a,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function pw(n){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function i(r,o,a){switch(t.calls++,o){case n.TRIANGLES:t.triangles+=a*(r/3);break;case n.LINES:t.lines+=a*(r/2);break;case n.LINE_STRIP:t.lines+=a*(r-1);break;case n.LINE_LOOP:t.lines+=a*r;break;case n.POINTS:t.points+=a*r;break;default:at("WebGLInfo: Unknown draw mode:",o);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:i}}function mw(n,e,t){let i=new WeakMap,s=new rn;function r(o,a,l){let c=o.morphTargetInfluences,h=a.morphAttributes.position||a.morphAttributes.normal||a.morphAttributes.color,f=h!==void 0?h.length:0,u=i.get(a);if(u===void 0||u.count!==f){let U=function(){_.dispose(),i.delete(a),a.removeEventListener("dispose",U)};u!==void 0&&u.texture.dispose();let m=a.morphAttributes.position!==void 0,g=a.morphAttributes.normal!==void 0,v=a.morphAttributes.color!==void 0,d=a.morphAttributes.position||[],p=a.morphAttributes.normal||[],x=a.morphAttributes.color||[],A=0;m===!0&&(A=1),g===!0&&(A=2),v===!0&&(A=3);let S=a.attributes.position.count*A,C=1;S>e.maxTextureSize&&(C=Math.ceil(S/e.maxTextureSize),S=e.maxTextureSize);let T=new Float32Array(S*C*4*f),_=new Ra(T,S,C,f);_.type=ki,_.needsUpdate=!0;let w=A*4;for(let N=0;N<f;N++){let R=d[N],G=p[N],B=x[N],L=S*C*4*N;for(let z=0;z<R.count;z++){let q=z*w;m===!0&&(s.fromBufferAttribute(R,z),T[L+q+0]=s.x,T[L+q+1]=s.y,T[L+q+2]=s.z,T[L+q+3]=0),g===!0&&(s.fromBufferAttribute(G,z),T[L+q+4]=s.x,T[L+q+5]=s.y,T[L+q+6]=s.z,T[L+q+7]=0),v===!0&&(s.fromBufferAttribute(B,z),T[L+q+8]=s.x,T[L+q+9]=s.y,T[L+q+10]=s.z,T[L+q+11]=B.itemSize===4?s.w:1)}}u={count:f,texture:_,size:new pt(S,C)},i.set(a,u),a.addEventListener("dispose",U)}if(o.isInstancedMesh===!0&&o.morphTexture!==null)l.getUniforms().setValue(n,"morphTexture",o.morphTexture,t);else{let m=0;for(let v=0;v<c.length;v++)m+=c[v];let g=a.morphTargetsRelative?1:1-m;l.getUniforms().setValue(n,"morphTargetBaseInfluence",g),l.getUniforms().setValue(n,"morphTargetInfluences",c)}l.getUniforms().setValue(n,"morphTargetsTexture",u.texture,t),l.getUniforms().setValue(n,"morphTargetsTextureSize",u.size)}return{update:r}}function gw(n,e,t,i,s){let r=new WeakMap;function o(c){let h=s.render.frame,f=c.geometry,u=e.get(c,f);if(r.get(u)!==h&&(e.update(u),r.set(u,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(t.update(c.instanceMatrix,n.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,n.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){let m=c.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return u}function a(){r=new WeakMap}function l(c){let h=c.target;h.removeEventListener("dispose",l),i.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:o,dispose:a}}var _w={[kf]:"LINEAR_TONE_MAPPING",[zf]:"REINHARD_TONE_MAPPING",[Gf]:"CINEON_TONE_MAPPING",[Hf]:"ACES_FILMIC_TONE_MAPPING",[Wf]:"AGX_TONE_MAPPING",[Xf]:"NEUTRAL_TONE_MAPPING",[Vf]:"CUSTOM_TONE_MAPPING"};function yw(n,e,t,i,s,r){let o=new _i(e,t,{type:n,depthBuffer:s,stencilBuffer:r,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),a=null,l=null,c=null,h=new ti;h.setAttribute("position",new Nn([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new Nn([0,2,0,0,2,0],2));let f=new Bc({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),u=new ts(h,f),m=new Jc(-1,1,1,-1,0,1),g=null,v=null,d=!1,p,x=null,A=[],S=!1;this.setSize=function(C,T){o.setSize(C,T),a!==null&&a.setSize(C,T),l!==null&&l.setSize(C,T);for(let _=0;_<A.length;_++){let w=A[_];w.setSize&&w.setSize(C,T)}},this.setEffects=function(C){A=C,S=A.length>0&&A[0].isRenderPass===!0;let T=o.width,_=o.height;A.length>0&&a===null&&(a=new _i(T,_,{type:zi,depthBuffer:!1,stencilBuffer:!1}),l=new _i(T,_,{type:zi,depthBuffer:!1,stencilBuffer:!1}));let w=s===!0&&A.some(U=>U.needsDepthTexture===!0);w!==(o.depthTexture!==null)&&(w===!0&&c===null&&(c=new Es(T,_),r===!0&&(c.format=As,c.type=Dr)),o.dispose(),o.depthTexture=w?c:null,o.resolveDepthBuffer=w,o.storeMultisampledDepthBuffer=w);for(let U=0;U<A.length;U++){let N=A[U];N.setSize&&N.setSize(T,_),w&&N.needsDepthTexture===!0&&N.setDepthTexture&&N.setDepthTexture(c)}},this.begin=function(C,T){if(d||C.toneMapping===ss&&A.length===0)return!1;if(x=T,T!==null){let _=T.width,w=T.height;(o.width!==_||o.height!==w)&&this.setSize(_,w)}return S===!1&&C.setRenderTarget(o),p=C.toneMapping,C.toneMapping=ss,!0},this.hasRenderPass=function(){return S},this.end=function(C,T){C.toneMapping=p,d=!0;let _=o,w=a;for(let U=0;U<A.length;U++){let N=A[U];N.enabled!==!1&&(N.render(C,w,_,T),N.needsSwap!==!1&&(_=w,w=w===a?l:a))}if(g!==C.outputColorSpace||v!==C.toneMapping){g=C.outputColorSpace,v=C.toneMapping,f.defines={},At.getTransfer(g)===Ft&&(f.defines.SRGB_TRANSFER="");let U=_w[v];U&&(f.defines[U]=""),f.needsUpdate=!0}f.uniforms.tDiffuse.value=_.texture,C.setRenderTarget(x),C.render(u,m),x=null,d=!1},this.isCompositing=function(){return d},this.dispose=function(){o.dispose(),a!==null&&a.dispose(),l!==null&&l.dispose(),h.dispose(),f.dispose()}}var f_=new Qn,d_=new Es(1,1),p_=new Oa(1),m_=new Ra,g_=new Pc,__=new Ua,X0=[],$0=[],q0=new Float32Array(16),Y0=new Float32Array(9),Z0=new Float32Array(4);function Go(n,e,t){let i=n[0];if(i<=0||i>0)return n;let s=e*t,r=X0[s];if(r===void 0&&(r=new Float32Array(s),X0[s]=r),e!==0){i.toArray(r,0);for(let o=1,a=0;o!==e;++o)a+=t,n[o].toArray(r,a)}return r}function Mn(n,e){if(n.length!==e.length)return!1;for(let t=0,i=n.length;t<i;t++)if(n[t]!==e[t])return!1;return!0}function wn(n,e){for(let t=0,i=e.length;t<i;t++)n[t]=e[t]}function Vh(n,e){let t=$0[e];t===void 0&&(t=new Int32Array(e),$0[e]=t);for(let i=0;i!==e;++i)t[i]=n.allocateTextureUnit();return t}function xw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function vw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;n.uniform2fv(this.addr,e),wn(t,e)}}function bw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(Mn(t,e))return;n.uniform3fv(this.addr,e),wn(t,e)}}function Sw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;n.uniform4fv(this.addr,e),wn(t,e)}}function Mw(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(Mn(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),wn(t,e)}else{if(Mn(t,i))return;Z0.set(i),n.uniformMatrix2fv(this.addr,!1,Z0),wn(t,i)}}function ww(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(Mn(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),wn(t,e)}else{if(Mn(t,i))return;Y0.set(i),n.uniformMatrix3fv(this.addr,!1,Y0),wn(t,i)}}function Ew(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(Mn(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),wn(t,e)}else{if(Mn(t,i))return;q0.set(i),n.uniformMatrix4fv(this.addr,!1,q0),wn(t,i)}}function Tw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function Aw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;n.uniform2iv(this.addr,e),wn(t,e)}}function Rw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Mn(t,e))return;n.uniform3iv(this.addr,e),wn(t,e)}}function Cw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;n.uniform4iv(this.addr,e),wn(t,e)}}function Iw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function Pw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;n.uniform2uiv(this.addr,e),wn(t,e)}}function Lw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Mn(t,e))return;n.uniform3uiv(this.addr,e),wn(t,e)}}function Nw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;n.uniform4uiv(this.addr,e),wn(t,e)}}function Wh(n){return n.version===0&&(n.compareFunction=id,n.needsUpdate=!0),n}function Dw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_2D_SHADOW?r=Wh(d_):r=f_,t.setTexture2D(e||r,s)}function Uw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture3D(e||g_,s)}function Ow(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_CUBE_SHADOW?r=Wh(p_):r=__,t.setTextureCube(e||r,s)}function Fw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture2DArray(e||m_,s)}function Bw(n){switch(n){case 5126:return xw;case 35664:return vw;case 35665:return bw;case 35666:return Sw;case 35674:return Mw;case 35675:return ww;case 35676:return Ew;case 5124:case 35670:return Tw;case 35667:case 35671:return Aw;case 35668:case 35672:return Rw;case 35669:case 35673:return Cw;case 5125:return Iw;case 36294:return Pw;case 36295:return Lw;case 36296:return Nw;case 35678:case 36198:case 36298:case 36306:case 35682:return Dw;case 35679:case 36299:case 36307:return Uw;case 35680:case 36300:case 36308:case 36293:return Ow;case 36289:case 36303:case 36311:case 36292:return Fw}}function kw(n,e){n.uniform1fv(this.addr,e)}function zw(n,e){let t=Go(e,this.size,2);n.uniform2fv(this.addr,t)}function Gw(n,e){let t=Go(e,this.size,3);n.uniform3fv(this.addr,t)}function Hw(n,e){let t=Go(e,this.size,4);n.uniform4fv(this.addr,t)}function Vw(n,e){let t=Go(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function Ww(n,e){let t=Go(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function Xw(n,e){let t=Go(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function $w(n,e){n.uniform1iv(this.addr,e)}function qw(n,e){n.uniform2iv(this.addr,e)}function Yw(n,e){n.uniform3iv(this.addr,e)}function Zw(n,e){n.uniform4iv(this.addr,e)}function Kw(n,e){n.uniform1uiv(this.addr,e)}function Jw(n,e){n.uniform2uiv(this.addr,e)}function jw(n,e){n.uniform3uiv(this.addr,e)}function Qw(n,e){n.uniform4uiv(this.addr,e)}function eE(n,e,t){let i=this.cache,s=e.length,r=Vh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));let o;this.type===n.SAMPLER_2D_SHADOW?o=Wh(d_):o=f_;for(let a=0;a!==s;++a)t.setTexture2D(e[a]||o,r[a])}function tE(n,e,t){let i=this.cache,s=e.length,r=Vh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));for(let o=0;o!==s;++o)t.setTexture3D(e[o]||g_,r[o])}function nE(n,e,t){let i=this.cache,s=e.length,r=Vh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));let o;this.type===n.SAMPLER_CUBE_SHADOW?o=Wh(p_):o=__;for(let a=0;a!==s;++a)t.setTextureCube(e[a]||o,r[a])}function iE(n,e,t){let i=this.cache,s=e.length,r=Vh(t,s);Mn(i,r)||(n.uniform1iv(this.addr,r),wn(i,r));for(let o=0;o!==s;++o)t.setTexture2DArray(e[o]||m_,r[o])}function sE(n){switch(n){case 5126:return kw;case 35664:return zw;case 35665:return Gw;case 35666:return Hw;case 35674:return Vw;case 35675:return Ww;case 35676:return Xw;case 5124:case 35670:return $w;case 35667:case 35671:return qw;case 35668:case 35672:return Yw;case 35669:case 35673:return Zw;case 5125:return Kw;case 36294:return Jw;case 36295:return jw;case 36296:return Qw;case 35678:case 36198:case 36298:case 36306:case 35682:return eE;case 35679:case 36299:case 36307:return tE;case 35680:case 36300:case 36308:case 36293:return nE;case 36289:case 36303:case 36311:case 36292:return iE}}var bd=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.setValue=Bw(t.type)}},Sd=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=sE(t.type)}},Md=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,i){let s=this.seq;for(let r=0,o=s.length;r!==o;++r){let a=s[r];a.setValue(e,t[a.id],i)}}},xd=/(\w+)(\])?(\[|\.)?/g;function K0(n,e){n.seq.push(e),n.map[e.id]=e}function rE(n,e,t){let i=n.name,s=i.length;for(xd.lastIndex=0;;){let r=xd.exec(i),o=xd.lastIndex,a=r[1],l=r[2]==="]",c=r[3];if(l&&(a=a|0),c===void 0||c==="["&&o+2===s){K0(t,c===void 0?new bd(a,n,e):new Sd(a,n,e));break}else{let f=t.map[a];f===void 0&&(f=new Md(a),K0(t,f)),t=f}}}var zo=class{constructor(e,t){this.seq=[],this.map={};let i=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let o=0;o<i;++o){let a=e.getActiveUniform(t,o),l=e.getUniformLocation(t,a.name);rE(a,l,this)}let s=[],r=[];for(let o of this.seq)o.type===e.SAMPLER_2D_SHADOW||o.type===e.SAMPLER_CUBE_SHADOW||o.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(o):r.push(o);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,i,s){let r=this.map[t];r!==void 0&&r.setValue(e,i,s)}setOptional(e,t,i){let s=t[i];s!==void 0&&this.setValue(e,i,s)}static upload(e,t,i,s){for(let r=0,o=t.length;r!==o;++r){let a=t[r],l=i[a.id];l.needsUpdate!==!1&&a.setValue(e,l.value,s)}}static seqWithValue(e,t){let i=[];for(let s=0,r=e.length;s!==r;++s){let o=e[s];o.id in t&&i.push(o)}return i}};function J0(n,e,t){let i=n.createShader(e);return n.shaderSource(i,t),n.compileShader(i),i}var oE=37297,aE=0;function lE(n,e){let t=n.split(`
`),i=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let o=s;o<r;o++){let a=o+1;i.push(`${a===e?">":" "} ${a}: ${t[o]}`)}return i.join(`
`)}var j0=new lt;function cE(n){At._getMatrix(j0,At.workingColorSpace,n);let e=`mat3( ${j0.elements.map(t=>t.toFixed(4))} )`;switch(At.getTransfer(n)){case Ea:return[e,"LinearTransferOETF"];case Ft:return[e,"sRGBTransferOETF"];default:return je("WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function Q0(n,e,t){let i=n.getShaderParameter(e,n.COMPILE_STATUS),r=(n.getShaderInfoLog(e)||"").trim();if(i&&r==="")return"";let o=/ERROR: 0:(\d+)/.exec(r);if(o){let a=parseInt(o[1]);return t.toUpperCase()+`

`+r+`

`+lE(n.getShaderSource(e),a)}else return r}function hE(n,e){let t=cE(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}var uE={[kf]:"Linear",[zf]:"Reinhard",[Gf]:"Cineon",[Hf]:"ACESFilmic",[Wf]:"AgX",[Xf]:"Neutral",[Vf]:"Custom"};function fE(n,e){let t=uE[e];return t===void 0?(je("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var zh=new J;function dE(){At.getLuminanceCoefficients(zh);let n=zh.x.toFixed(4),e=zh.y.toFixed(4),t=zh.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function pE(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Qa).join(`
`)}function mE(n){let e=[];for(let t in n){let i=n[t];i!==!1&&e.push("#define "+t+" "+i)}return e.join(`
`)}function gE(n,e){let t={},i=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let s=0;s<i;s++){let r=n.getActiveAttrib(e,s),o=r.name,a=1;r.type===n.FLOAT_MAT2&&(a=2),r.type===n.FLOAT_MAT3&&(a=3),r.type===n.FLOAT_MAT4&&(a=4),t[o]={type:r.type,location:n.getAttribLocation(e,o),locationSize:a}}return t}function Qa(n){return n!==""}function e_(n,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function t_(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var _E=/^[ \t]*#include +<([\w\d./]+)>/gm;function wd(n){return n.replace(_E,yE)}function yE(n,e){let t=yt[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return wd(t)}var xE=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function n_(n){return n.replace(xE,vE)}function vE(n,e,t,i){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=i.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function i_(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}var bE={[Wa]:"SHADOWMAP_TYPE_PCF",[Uo]:"SHADOWMAP_TYPE_VSM"};function SE(n){return bE[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}var ME={[Fo]:"ENVMAP_MODE_REFRACTION"};function wE(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":ME[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}var EE={[Bf]:"ENVMAP_BLENDING_MULTIPLY",[x0]:"ENVMAP_BLENDING_MIX",[v0]:"ENVMAP_BLENDING_ADD"};function TE(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":EE[n.combine]||"ENVMAP_BLENDING_NONE"}function AE(n,e,t,i){let s=n.getContext(),r=t.defines,o=t.vertexShader,a=t.fragmentShader,l=SE(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=wE(t),f=TE(t),u=pE(t),m=mE(r),g=s.createProgram(),v,d,p=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(v=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Qa).join(`
`),v.length>0&&(v+=`
`),d=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Qa).join(`
`),d.length>0&&(d+=`
`)):(v=[i_(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Qa).join(`
`),d=[i_(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+h:"",t.envMap?"#define "+f:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==ss?"#define TONE_MAPPING":"",t.toneMapping!==ss?yt.tonemapping_pars_fragment:"",t.toneMapping!==ss?fE("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",yt.colorspace_pars_fragment,hE("linearToOutputTexel",t.outputColorSpace),dE(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Qa).join(`
`)),o=wd(o),o=e_(o,t),o=t_(o,t),a=wd(a),a=e_(a,t),a=t_(a,t),o=n_(o),a=n_(a),t.isRawShaderMaterial!==!0&&(p=`#version 300 es
`,v=[u,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+v,d=["#define varying in",t.glslVersion===sd?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===sd?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+d);let x=p+v+o,A=p+d+a,S=J0(s,s.VERTEX_SHADER,x),C=J0(s,s.FRAGMENT_SHADER,A);s.attachShader(g,S),s.attachShader(g,C),t.index0AttributeName!==void 0?s.bindAttribLocation(g,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(g,0,"position"),s.linkProgram(g);function T(N){if(n.debug.checkShaderErrors){let R=s.getProgramInfoLog(g)||"",G=s.getShaderInfoLog(S)||"",B=s.getShaderInfoLog(C)||"",L=R.trim(),z=G.trim(),q=B.trim(),O=!0,re=!0;if(s.getProgramParameter(g,s.LINK_STATUS)===!1)if(O=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(s,g,S,C);else{let X=Q0(s,S,"vertex"),$=Q0(s,C,"fragment");at("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(g,s.VALIDATE_STATUS)+`

Material Name: `+N.name+`
Material Type: `+N.type+`

Program Info Log: `+L+`
`+X+`
`+$)}else L!==""?je("WebGLProgram: Program Info Log:",L):(z===""||q==="")&&(re=!1);re&&(N.diagnostics={runnable:O,programLog:L,vertexShader:{log:z,prefix:v},fragmentShader:{log:q,prefix:d}})}s.deleteShader(S),s.deleteShader(C),_=new zo(s,g),w=gE(s,g)}let _;this.getUniforms=function(){return _===void 0&&T(this),_};let w;this.getAttributes=function(){return w===void 0&&T(this),w};let U=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return U===!1&&(U=s.getProgramParameter(g,oE)),U},this.destroy=function(){i.releaseStatesOfProgram(this),s.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=aE++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=S,this.fragmentShader=C,this}var RE=0,Ed=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,i){let s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(i)===!1&&(s.add(i),i.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let i of t)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,i=t.get(e);return i===void 0&&(i=new Set,t.set(e,i)),i}_getShaderStage(e){let t=this.shaderCache,i=t.get(e);return i===void 0&&(i=new Td(e),t.set(e,i)),i}},Td=class{constructor(e){this.id=RE++,this.code=e,this.usedTimes=0}};function CE(n){return n===lr||n===Ka||n===Ja}function IE(n,e,t,i,s,r){let o=new Ca,a=new Ed,l=new Set,c=[],h=new Map,f=i.logarithmicDepthBuffer,u={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(_){return l.add(_),_===0?"uv":`uv${_}`}function g(_,w,U,N,R,G){let B=N.fog,L=R.geometry,z=_.isMeshStandardMaterial||_.isMeshLambertMaterial||_.isMeshPhongMaterial?N.environment:null,q=_.isMeshStandardMaterial||_.isMeshLambertMaterial&&!_.envMap||_.isMeshPhongMaterial&&!_.envMap,O=e.get(_.envMap||z,q),re=u[_.type],X=i.precision;_.precision!==null&&(X=i.getMaxPrecision(_.precision),X!==_.precision&&je("WebGLProgram.getParameters:",_.precision,"not supported, using",X,"instead."));let $=L.morphAttributes.position||L.morphAttributes.normal||L.morphAttributes.color,W=$!==void 0?$.length:0,ne=0;L.morphAttributes.position!==void 0&&(ne=1),L.morphAttributes.normal!==void 0&&(ne=2),L.morphAttributes.color!==void 0&&(ne=3);let le,Q,me,pe;if(re){let Pe=os[re];le=Pe.vertexShader,Q=Pe.fragmentShader}else{le=_.vertexShader,Q=_.fragmentShader;let Pe=a.getVertexShaderStage(_),mt=a.getFragmentShaderStage(_);a.update(_,Pe,mt),me=Pe.id,pe=mt.id}let be=n.getRenderTarget(),xe=n.state.buffers.depth.getReversed(),We=R.isInstancedMesh===!0,Qe=R.isBatchedMesh===!0,Ne=!!_.map,qe=!!_.matcap,tt=!!O,fe=tt&&O.isPMREMTexture===!0,ke=!!_.aoMap,Ze=!!_.lightMap,Rt=!!_.bumpMap&&_.wireframe===!1,wt=!!_.normalMap,Vt=!!_.displacementMap,et=!!_.emissiveMap,Ct=!!_.metalnessMap,ut=!!_.roughnessMap,ft=_.anisotropy>0,F=_.clearcoat>0,ge=_.diffuseRoughness>0,Ke=_.dispersion>0,dt=_.retroreflectivity>0,Ae=_.iridescence>0,Wt=_.sheen>0,Xe=_.transmission>0,Je=ft&&!!_.anisotropyMap,I=F&&!!_.clearcoatMap,b=F&&!!_.clearcoatNormalMap,Y=F&&!!_.clearcoatRoughnessMap,de=ge&&!!_.diffuseRoughnessMap,ce=Ae&&!!_.iridescenceMap,Me=Ae&&!!_.iridescenceThicknessMap,we=Wt&&!!_.sheenColorMap,ie=Wt&&!!_.sheenRoughnessMap,oe=!!_.specularMap,ye=!!_.specularColorMap,k=!!_.specularIntensityMap,ae=Xe&&!!_.transmissionMap,se=Xe&&!!_.thicknessMap,Re=!!_.gradientMap,Se=!!_.alphaMap,Te=_.alphaTest>0,$e=!!_.alphaHash,st=!!_.extensions,ue=ss;_.toneMapped&&(be===null||be.isXRRenderTarget===!0)&&(ue=n.toneMapping);let Ge=fe?O.isCompressedCubeTexture?O.image[0].mipmaps:O.mipmaps:null,rt={shaderID:re,shaderType:_.type,shaderName:_.name,vertexShader:le,fragmentShader:Q,defines:_.defines,customVertexShaderID:me,customFragmentShaderID:pe,isRawShaderMaterial:_.isRawShaderMaterial===!0,glslVersion:_.glslVersion,precision:X,batching:Qe,batchingColor:Qe&&R._colorsTexture!==null,instancing:We,instancingColor:We&&R.instanceColor!==null,instancingMorph:We&&R.morphTexture!==null,outputColorSpace:be===null?n.outputColorSpace:be.isXRRenderTarget===!0?be.texture.colorSpace:At.workingColorSpace,alphaToCoverage:!!_.alphaToCoverage,map:Ne,matcap:qe,envMap:tt,envMapMode:tt&&O.mapping,envMapPMREM:fe,envMapMaxLod:fe?Ge.length-1:null,envMapSize:fe?Ge[0].width:null,aoMap:ke,lightMap:Ze,bumpMap:Rt,normalMap:wt,displacementMap:Vt,emissiveMap:et,normalMapObjectSpace:wt&&_.normalMapType===M0,normalMapTangentSpace:wt&&_.normalMapType===ed,packedNormalMap:wt&&_.normalMapType===ed&&CE(_.normalMap.format),metalnessMap:Ct,roughnessMap:ut,anisotropy:ft,anisotropyMap:Je,clearcoat:F,clearcoatMap:I,clearcoatNormalMap:b,clearcoatRoughnessMap:Y,diffuseRoughness:ge,diffuseRoughnessMap:de,dispersion:Ke,retroreflection:dt,iridescence:Ae,iridescenceMap:ce,iridescenceThicknessMap:Me,sheen:Wt,sheenColorMap:we,sheenRoughnessMap:ie,specularMap:oe,specularColorMap:ye,specularIntensityMap:k,transmission:Xe,transmissionMap:ae,thicknessMap:se,gradientMap:Re,opaque:_.transparent===!1&&_.blending===Oo&&_.alphaToCoverage===!1,alphaMap:Se,alphaTest:Te,alphaHash:$e,combine:_.combine,mapUv:Ne&&m(_.map.channel),aoMapUv:ke&&m(_.aoMap.channel),lightMapUv:Ze&&m(_.lightMap.channel),bumpMapUv:Rt&&m(_.bumpMap.channel),normalMapUv:wt&&m(_.normalMap.channel),displacementMapUv:Vt&&m(_.displacementMap.channel),emissiveMapUv:et&&m(_.emissiveMap.channel),metalnessMapUv:Ct&&m(_.metalnessMap.channel),roughnessMapUv:ut&&m(_.roughnessMap.channel),anisotropyMapUv:Je&&m(_.anisotropyMap.channel),clearcoatMapUv:I&&m(_.clearcoatMap.channel),clearcoatNormalMapUv:b&&m(_.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:Y&&m(_.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:de&&m(_.diffuseRoughnessMap.channel),iridescenceMapUv:ce&&m(_.iridescenceMap.channel),iridescenceThicknessMapUv:Me&&m(_.iridescenceThicknessMap.channel),sheenColorMapUv:we&&m(_.sheenColorMap.channel),sheenRoughnessMapUv:ie&&m(_.sheenRoughnessMap.channel),specularMapUv:oe&&m(_.specularMap.channel),specularColorMapUv:ye&&m(_.specularColorMap.channel),specularIntensityMapUv:k&&m(_.specularIntensityMap.channel),transmissionMapUv:ae&&m(_.transmissionMap.channel),thicknessMapUv:se&&m(_.thicknessMap.channel),alphaMapUv:Se&&m(_.alphaMap.channel),vertexTangents:!!L.attributes.tangent&&(wt||ft),vertexNormals:!!L.attributes.normal,vertexColors:_.vertexColors,vertexAlphas:_.vertexColors===!0&&!!L.attributes.color&&L.attributes.color.itemSize===4,pointsUvs:R.isPoints===!0&&!!L.attributes.uv&&(Ne||Se),fog:!!B,useFog:_.fog===!0,fogExp2:!!B&&B.isFogExp2,flatShading:_.wireframe===!1&&(_.flatShading===!0||L.attributes.normal===void 0&&wt===!1&&(_.isMeshLambertMaterial||_.isMeshPhongMaterial||_.isMeshStandardMaterial||_.isMeshPhysicalMaterial)),sizeAttenuation:_.sizeAttenuation===!0,logarithmicDepthBuffer:f,reversedDepthBuffer:xe,skinning:R.isSkinnedMesh===!0,hasPositionAttribute:L.attributes.position!==void 0,morphTargets:L.morphAttributes.position!==void 0,morphNormals:L.morphAttributes.normal!==void 0,morphColors:L.morphAttributes.color!==void 0,morphTargetsCount:W,morphTextureStride:ne,numSunLights:w.sun.length,numDirLights:w.directional.length,numPointLights:w.point.length,numSpotLights:w.spot.length,numSpotLightMaps:w.spotLightMap.length,numRectAreaLights:w.rectArea.length,numHemiLights:w.hemi.length,numSunLightShadows:w.sunShadowMap.length,numDirLightShadows:w.directionalShadowMap.length,numPointLightShadows:w.pointShadowMap.length,numSpotLightShadows:w.spotShadowMap.length,numSpotLightShadowsWithMaps:w.numSpotLightShadowsWithMaps,numLightProbes:w.numLightProbes,numLightProbeGrids:G.filter(Pe=>Pe.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:_.dithering,shadowMapEnabled:n.shadowMap.enabled&&U.length>0,shadowMapType:n.shadowMap.type,toneMapping:ue,decodeVideoTexture:Ne&&_.map.isVideoTexture===!0&&At.getTransfer(_.map.colorSpace)===Ft,decodeVideoTextureEmissive:et&&_.emissiveMap.isVideoTexture===!0&&At.getTransfer(_.emissiveMap.colorSpace)===Ft,premultipliedAlpha:_.premultipliedAlpha,doubleSided:_.side===is,flipSided:_.side===Kn,useDepthPacking:_.depthPacking>=0,depthPacking:_.depthPacking||0,index0AttributeName:_.index0AttributeName,extensionClipCullDistance:st&&_.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(st&&_.extensions.multiDraw===!0||Qe)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:_.customProgramCacheKey()};return rt.vertexUv1s=l.has(1),rt.vertexUv2s=l.has(2),rt.vertexUv3s=l.has(3),l.clear(),rt}function v(_){let w=[];if(_.shaderID?w.push(_.shaderID):(w.push(_.customVertexShaderID),w.push(_.customFragmentShaderID)),_.defines!==void 0)for(let U in _.defines)w.push(U),w.push(_.defines[U]);return _.isRawShaderMaterial===!1&&(d(w,_),p(w,_),w.push(n.outputColorSpace)),w.push(_.customProgramCacheKey),w.join()}function d(_,w){_.push(w.precision),_.push(w.outputColorSpace),_.push(w.envMapMode),_.push(w.envMapPMREM),_.push(w.envMapMaxLod),_.push(w.envMapSize),_.push(w.mapUv),_.push(w.alphaMapUv),_.push(w.lightMapUv),_.push(w.aoMapUv),_.push(w.bumpMapUv),_.push(w.normalMapUv),_.push(w.displacementMapUv),_.push(w.emissiveMapUv),_.push(w.metalnessMapUv),_.push(w.roughnessMapUv),_.push(w.anisotropyMapUv),_.push(w.clearcoatMapUv),_.push(w.clearcoatNormalMapUv),_.push(w.clearcoatRoughnessMapUv),_.push(w.diffuseRoughnessMapUv),_.push(w.iridescenceMapUv),_.push(w.iridescenceThicknessMapUv),_.push(w.sheenColorMapUv),_.push(w.sheenRoughnessMapUv),_.push(w.specularMapUv),_.push(w.specularColorMapUv),_.push(w.specularIntensityMapUv),_.push(w.transmissionMapUv),_.push(w.thicknessMapUv),_.push(w.combine),_.push(w.fogExp2),_.push(w.sizeAttenuation),_.push(w.morphTargetsCount),_.push(w.numSunLights),_.push(w.numDirLights),_.push(w.numPointLights),_.push(w.numSpotLights),_.push(w.numSpotLightMaps),_.push(w.numHemiLights),_.push(w.numRectAreaLights),_.push(w.numSunLightShadows),_.push(w.numDirLightShadows),_.push(w.numPointLightShadows),_.push(w.numSpotLightShadows),_.push(w.numSpotLightShadowsWithMaps),_.push(w.numLightProbes),_.push(w.numLightProbeGrids),_.push(w.shadowMapType),_.push(w.toneMapping),_.push(w.numClippingPlanes),_.push(w.numClipIntersection),_.push(w.depthPacking)}function p(_,w){o.disableAll(),w.instancing&&o.enable(0),w.instancingColor&&o.enable(1),w.instancingMorph&&o.enable(2),w.matcap&&o.enable(3),w.envMap&&o.enable(4),w.normalMapObjectSpace&&o.enable(5),w.normalMapTangentSpace&&o.enable(6),w.clearcoat&&o.enable(7),w.iridescence&&o.enable(8),w.alphaTest&&o.enable(9),w.vertexColors&&o.enable(10),w.vertexAlphas&&o.enable(11),w.vertexUv1s&&o.enable(12),w.vertexUv2s&&o.enable(13),w.vertexUv3s&&o.enable(14),w.vertexTangents&&o.enable(15),w.anisotropy&&o.enable(16),w.alphaHash&&o.enable(17),w.batching&&o.enable(18),w.dispersion&&o.enable(19),w.retroreflection&&o.enable(24),w.diffuseRoughness&&o.enable(25),w.batchingColor&&o.enable(20),w.gradientMap&&o.enable(21),w.packedNormalMap&&o.enable(22),w.vertexNormals&&o.enable(23),_.push(o.mask),o.disableAll(),w.fog&&o.enable(0),w.useFog&&o.enable(1),w.flatShading&&o.enable(2),w.logarithmicDepthBuffer&&o.enable(3),w.reversedDepthBuffer&&o.enable(4),w.skinning&&o.enable(5),w.morphTargets&&o.enable(6),w.morphNormals&&o.enable(7),w.morphColors&&o.enable(8),w.premultipliedAlpha&&o.enable(9),w.shadowMapEnabled&&o.enable(10),w.doubleSided&&o.enable(11),w.flipSided&&o.enable(12),w.useDepthPacking&&o.enable(13),w.dithering&&o.enable(14),w.transmission&&o.enable(15),w.sheen&&o.enable(16),w.opaque&&o.enable(17),w.pointsUvs&&o.enable(18),w.decodeVideoTexture&&o.enable(19),w.decodeVideoTextureEmissive&&o.enable(20),w.alphaToCoverage&&o.enable(21),w.numLightProbeGrids>0&&o.enable(22),w.hasPositionAttribute&&o.enable(23),_.push(o.mask)}function x(_){let w=u[_.type],U;if(w){let N=os[w];U=B0.clone(N.uniforms)}else U=_.uniforms;return U}function A(_,w){let U=h.get(w);return U!==void 0?++U.usedTimes:(U=new AE(n,w,_,s),c.push(U),h.set(w,U)),U}function S(_){if(--_.usedTimes===0){let w=c.indexOf(_);c[w]=c[c.length-1],c.pop(),h.delete(_.cacheKey),_.destroy()}}function C(_){a.remove(_)}function T(){a.dispose()}return{getParameters:g,getProgramCacheKey:v,getUniforms:x,acquireProgram:A,releaseProgram:S,releaseShaderCache:C,programs:c,dispose:T}}function PE(){let n=new WeakMap;function e(o){return n.has(o)}function t(o){let a=n.get(o);return a===void 0&&(a={},n.set(o,a)),a}function i(o){n.delete(o)}function s(o,a,l){n.get(o)[a]=l}function r(){n=new WeakMap}return{has:e,get:t,remove:i,update:s,dispose:r}}function LE(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.materialVariant!==e.materialVariant?n.materialVariant-e.materialVariant:n.z!==e.z?n.z-e.z:n.id-e.id}function s_(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function r_(){let n=[],e=0,t=[],i=[],s=[];function r(){e=0,t.length=0,i.length=0,s.length=0}function o(u){let m=0;return u.isInstancedMesh&&(m+=2),u.isSkinnedMesh&&(m+=1),m}function a(u,m,g,v,d,p){let x=n[e];return x===void 0?(x={id:u.id,object:u,geometry:m,material:g,materialVariant:o(u),groupOrder:v,renderOrder:u.renderOrder,z:d,group:p},n[e]=x):(x.id=u.id,x.object=u,x.geometry=m,x.material=g,x.materialVariant=o(u),x.groupOrder=v,x.renderOrder=u.renderOrder,x.z=d,x.group=p),e++,x}function l(u,m,g,v,d,p,x){x.reversedDepth===!0&&(d=-d);let A=a(u,m,g,v,d,p);g.transmission>0?i.push(A):g.transparent===!0?s.push(A):t.push(A)}function c(u,m,g,v,d,p){let x=a(u,m,g,v,d,p);g.transmission>0?i.unshift(x):g.transparent===!0?s.unshift(x):t.unshift(x)}function h(u,m){t.length>1&&t.sort(u||LE),i.length>1&&i.sort(m||s_),s.length>1&&s.sort(m||s_)}function f(){for(let u=e,m=n.length;u<m;u++){let g=n[u];if(g.id===null)break;g.id=null,g.object=null,g.geometry=null,g.material=null,g.group=null}}return{opaque:t,transmissive:i,transparent:s,init:r,push:l,unshift:c,finish:f,sort:h}}function NE(){let n=new WeakMap;function e(i,s){let r=n.get(i),o;return r===void 0?(o=new r_,n.set(i,[o])):s>=r.length?(o=new r_,r.push(o)):o=r[s],o}function t(){n=new WeakMap}return{get:e,dispose:t}}function DE(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new J,color:new _t};break;case"SpotLight":t={position:new J,direction:new J,color:new _t,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new J,color:new _t,distance:0,decay:0};break;case"HemisphereLight":t={direction:new J,skyColor:new _t,groundColor:new _t};break;case"RectAreaLight":t={color:new _t,position:new J,halfWidth:new J,halfHeight:new J};break}return n[e.id]=t,t}}}function UE(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new pt};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new pt};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new pt,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}var OE=0;function FE(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function BE(n){let e=new DE,t=UE(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)i.probe.push(new J);let s=new J,r=new tn,o=new tn;function a(c){let h=0,f=0,u=0;for(let G=0;G<9;G++)i.probe[G].set(0,0,0);let m=0,g=0,v=0,d=0,p=0,x=0,A=0,S=0,C=0,T=0,_=0,w=0,U=0,N=0;c.sort(FE);for(let G=0,B=c.length;G<B;G++){let L=c[G],z=L.color,q=L.intensity,O=L.distance,re=null;if(L.shadow&&L.shadow.map&&(L.shadow.map.texture.format===lr?re=L.shadow.map.texture:re=L.shadow.map.depthTexture||L.shadow.map.texture),L.isAmbientLight)h+=z.r*q,f+=z.g*q,u+=z.b*q;else if(L.isLightProbe){for(let X=0;X<9;X++)i.probe[X].addScaledVector(L.sh.coefficients[X],q);N++}else if(L.isSunLight){let X=e.get(L);if(X.color.copy(L.color).multiplyScalar(L.intensity),L.castShadow){let $=L.shadow,W=t.get(L);W.shadowIntensity=$.intensity,W.shadowBias=$.bias,W.shadowNormalBias=$.normalBias,W.shadowRadius=$.radius,W.shadowMapSize.copy($.mapSize).multiply($.getFrameExtents()),i.sunShadow[g]=W,i.sunShadowMap[g]=re;let ne=$.getViewportCount();for(let le=0;le<ne;le++)i.sunShadowMatrix[v+le]=$.getMatrix(le),i.sunShadowCascade[v+le]=$._cascadeData[le];v+=ne,g++}i.sun[m]=X,m++}else if(L.isDirectionalLight){let X=e.get(L);if(X.color.copy(L.color).multiplyScalar(L.intensity),L.castShadow){let $=L.shadow,W=t.get(L);W.shadowIntensity=$.intensity,W.shadowBias=$.bias,W.shadowNormalBias=$.normalBias,W.shadowRadius=$.radius,W.shadowMapSize=$.mapSize,i.directionalShadow[d]=W,i.directionalShadowMap[d]=re,i.directionalShadowMatrix[d]=L.shadow.matrix,C++}i.directional[d]=X,d++}else if(L.isSpotLight){let X=e.get(L);X.position.setFromMatrixPosition(L.matrixWorld),X.color.copy(z).multiplyScalar(q),X.distance=O,X.coneCos=Math.cos(L.angle),X.penumbraCos=Math.cos(L.angle*(1-L.penumbra)),X.decay=L.decay,i.spot[x]=X;let $=L.shadow;if(L.map&&(i.spotLightMap[w]=L.map,w++,$.updateMatrices(L),L.castShadow&&U++),i.spotLightMatrix[x]=$.matrix,L.castShadow){let W=t.get(L);W.shadowIntensity=$.intensity,W.shadowBias=$.bias,W.shadowNormalBias=$.normalBias,W.shadowRadius=$.radius,W.shadowMapSize=$.mapSize,i.spotShadow[x]=W,i.spotShadowMap[x]=re,_++}x++}else if(L.isRectAreaLight){let X=e.get(L);X.color.copy(z).multiplyScalar(q),X.halfWidth.set(L.width*.5,0,0),X.halfHeight.set(0,L.height*.5,0),i.rectArea[A]=X,A++}else if(L.isPointLight){let X=e.get(L);if(X.color.copy(L.color).multiplyScalar(L.intensity),X.distance=L.distance,X.decay=L.decay,L.castShadow){let $=L.shadow,W=t.get(L);W.shadowIntensity=$.intensity,W.shadowBias=$.bias,W.shadowNormalBias=$.normalBias,W.shadowRadius=$.radius,W.shadowMapSize=$.mapSize,W.shadowCameraNear=$.camera.near,W.shadowCameraFar=$.camera.far,i.pointShadow[p]=W,i.pointShadowMap[p]=re,i.pointShadowMatrix[p]=L.shadow.matrix,T++}i.point[p]=X,p++}else if(L.isHemisphereLight){let X=e.get(L);X.skyColor.copy(L.color).multiplyScalar(q),X.groundColor.copy(L.groundColor).multiplyScalar(q),i.hemi[S]=X,S++}}A>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=Ue.LTC_FLOAT_1,i.rectAreaLTC2=Ue.LTC_FLOAT_2):(i.rectAreaLTC1=Ue.LTC_HALF_1,i.rectAreaLTC2=Ue.LTC_HALF_2)),i.ambient[0]=h,i.ambient[1]=f,i.ambient[2]=u;let R=i.hash;(R.sunLength!==m||R.directionalLength!==d||R.pointLength!==p||R.spotLength!==x||R.rectAreaLength!==A||R.hemiLength!==S||R.numSunShadows!==g||R.numDirectionalShadows!==C||R.numPointShadows!==T||R.numSpotShadows!==_||R.numSpotMaps!==w||R.numLightProbes!==N)&&(i.sun.length=m,i.directional.length=d,i.spot.length=x,i.rectArea.length=A,i.point.length=p,i.hemi.length=S,i.sunShadow.length=g,i.sunShadowMap.length=g,i.sunShadowMatrix.length=v,i.sunShadowCascade.length=v,i.directionalShadow.length=C,i.directionalShadowMap.length=C,i.directionalShadowMatrix.length=C,i.pointShadow.length=T,i.pointShadowMap.length=T,i.pointShadowMatrix.length=T,i.spotShadow.length=_,i.spotShadowMap.length=_,i.spotLightMatrix.length=_+w-U,i.spotLightMap.length=w,i.numSpotLightShadowsWithMaps=U,i.numLightProbes=N,R.sunLength=m,R.directionalLength=d,R.pointLength=p,R.spotLength=x,R.rectAreaLength=A,R.hemiLength=S,R.numSunShadows=g,R.numDirectionalShadows=C,R.numPointShadows=T,R.numSpotShadows=_,R.numSpotMaps=w,R.numLightProbes=N,i.version=OE++)}function l(c,h){let f=0,u=0,m=0,g=0,v=0,d=0,p=h.matrixWorldInverse;for(let x=0,A=c.length;x<A;x++){let S=c[x];if(S.isSunLight){let C=i.sun[f];C.direction.setFromMatrixPosition(S.matrixWorld),C.direction.transformDirection(p),f++}else if(S.isDirectionalLight){let C=i.directional[u];C.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(p),u++}else if(S.isSpotLight){let C=i.spot[g];C.position.setFromMatrixPosition(S.matrixWorld),C.position.applyMatrix4(p),C.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(p),g++}else if(S.isRectAreaLight){let C=i.rectArea[v];C.position.setFromMatrixPosition(S.matrixWorld),C.position.applyMatrix4(p),o.identity(),r.copy(S.matrixWorld),r.premultiply(p),o.extractRotation(r),C.halfWidth.set(S.width*.5,0,0),C.halfHeight.set(0,S.height*.5,0),C.halfWidth.applyMatrix4(o),C.halfHeight.applyMatrix4(o),v++}else if(S.isPointLight){let C=i.point[m];C.position.setFromMatrixPosition(S.matrixWorld),C.position.applyMatrix4(p),m++}else if(S.isHemisphereLight){let C=i.hemi[d];C.direction.setFromMatrixPosition(S.matrixWorld),C.direction.transformDirection(p),d++}}}return{setup:a,setupView:l,state:i}}function o_(n){let e=new BE(n),t=[],i=[],s=[];function r(f){h.camera=f,t.length=0,i.length=0,s.length=0}function o(f){f.isLightProbeGrid?s.push(f):t.push(f)}function a(f){i.push(f)}function l(){e.setup(t),s.sort((f,u)=>f.priority-u.priority||f.id-u.id)}function c(f){e.setupView(t,f)}let h={lightsArray:t,shadowsArray:i,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:o,pushShadow:a}}function kE(n){let e=new WeakMap;function t(s,r=0){let o=e.get(s),a;return o===void 0?(a=new o_(n),e.set(s,[a])):r>=o.length?(a=new o_(n),o.push(a)):a=o[r],a}function i(){e=new WeakMap}return{get:t,dispose:i}}var zE=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,GE=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,HE=[new J(1,0,0),new J(-1,0,0),new J(0,1,0),new J(0,-1,0),new J(0,0,1),new J(0,0,-1)],VE=[new J(0,-1,0),new J(0,-1,0),new J(0,0,1),new J(0,0,-1),new J(0,-1,0),new J(0,-1,0)],a_=new tn,ja=new J,vd=new J;function WE(n,e,t){let i=new Ir,s=new pt,r=new pt,o=new rn,a=new kc,l=new zc,c={},h=t.maxTextureSize,f={[ar]:Kn,[Kn]:ar,[is]:is},u=new ns({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new pt},radius:{value:4}},vertexShader:zE,fragmentShader:GE}),m=u.clone();m.defines.HORIZONTAL_PASS=1;let g=new ti;g.setAttribute("position",new mi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let v=new ts(g,u),d=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Wa;let p=this.type;this.render=function(T,_,w){if(d.enabled===!1||d.autoUpdate===!1&&d.needsUpdate===!1||T.length===0)return;this.type===e0&&(je("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Wa);let U=n.getRenderTarget(),N=n.getActiveCubeFace(),R=n.getActiveMipmapLevel(),G=n.state;G.setBlending(Pr),G.buffers.depth.getReversed()===!0?G.buffers.color.setClear(0,0,0,0):G.buffers.color.setClear(1,1,1,1),G.buffers.depth.setTest(!0),G.setScissorTest(!1);let B=p!==this.type;B&&_.traverse(function(L){L.material&&(Array.isArray(L.material)?L.material.forEach(z=>z.needsUpdate=!0):L.material.needsUpdate=!0)});for(let L=0,z=T.length;L<z;L++){let q=T[L],O=q.shadow;if(O===void 0){je("WebGLShadowMap:",q,"has no shadow.");continue}if(O.autoUpdate===!1&&O.needsUpdate===!1)continue;s.copy(O.mapSize);let re=O.getFrameExtents();s.multiply(re),r.copy(O.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/re.x),s.x=r.x*re.x,O.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/re.y),s.y=r.y*re.y,O.mapSize.y=r.y));let X=n.state.buffers.depth.getReversed();if(O.camera._reversedDepth=X,O.map===null||B===!0){if(O.map!==null&&(O.map.depthTexture!==null&&(O.map.depthTexture.dispose(),O.map.depthTexture=null),O.map.dispose()),this.type===Uo){if(q.isPointLight){je("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}O.map=new _i(s.x,s.y,{format:lr,type:zi,minFilter:Zn,magFilter:Zn,generateMipmaps:!1}),O.map.texture.name=q.name+".shadowMap",O.map.depthTexture=new Es(s.x,s.y,ki),O.map.depthTexture.name=q.name+".shadowMapDepth",O.map.depthTexture.format=Ms,O.map.depthTexture.compareFunction=null,O.map.depthTexture.minFilter=Dn,O.map.depthTexture.magFilter=Dn}else q.isPointLight?(O.map=new el(s.x),O.map.depthTexture=new Oa(s.x,Bi)):(O.map=new _i(s.x,s.y),O.map.depthTexture=new Es(s.x,s.y,Bi)),O.map.depthTexture.name=q.name+".shadowMap",O.map.depthTexture.format=Ms,this.type===Wa?(O.map.depthTexture.compareFunction=X?nd:td,O.map.depthTexture.minFilter=Zn,O.map.depthTexture.magFilter=Zn):(O.map.depthTexture.compareFunction=null,O.map.depthTexture.minFilter=Dn,O.map.depthTexture.magFilter=Dn);O.camera.updateProjectionMatrix()}O.map.isWebGLCubeRenderTarget!==!0&&(O.map.width!==s.x||O.map.height!==s.y)&&O.map.setSize(s.x,s.y);let $=O.map.isWebGLCubeRenderTarget?6:O.getViewportCount();q.isPointLight!==!0&&O.updateMatrices(q,w);let W=(O.camera.layers.mask&4294967294)!==0?O.camera.layers:w.layers;for(let ne=0;ne<$;ne++){let le=O.getCamera(ne);if(q.isPointLight){let Q=O.camera,me=O.matrix,pe=q.distance||Q.far;pe!==Q.far&&(Q.far=pe,Q.updateProjectionMatrix()),ja.setFromMatrixPosition(q.matrixWorld),Q.position.copy(ja),vd.copy(Q.position),vd.add(HE[ne]),Q.up.copy(VE[ne]),Q.lookAt(vd),Q.updateMatrixWorld(),me.makeTranslation(-ja.x,-ja.y,-ja.z),a_.multiplyMatrices(Q.projectionMatrix,Q.matrixWorldInverse),O._frustum.setFromProjectionMatrix(a_,Q.coordinateSystem,Q.reversedDepth)}if(O.map.isWebGLCubeRenderTarget)n.setRenderTarget(O.map,ne),n.clear();else{ne===0&&(n.setRenderTarget(O.map),n.clear());let Q=O.getViewport(ne);o.set(r.x*Q.x,r.y*Q.y,r.x*Q.z,r.y*Q.w),G.viewport(o)}i=O.getFrustum(ne),S(_,w,le,q,W,this.type)}O.isPointLightShadow!==!0&&this.type===Uo&&x(O,w),O.needsUpdate=!1}p=this.type,d.needsUpdate=!1,n.setRenderTarget(U,N,R)};function x(T,_){let w=e.update(v);u.defines.VSM_SAMPLES!==T.blurSamples&&(u.defines.VSM_SAMPLES=T.blurSamples,m.defines.VSM_SAMPLES=T.blurSamples,u.needsUpdate=!0,m.needsUpdate=!0),T.mapPass===null?T.mapPass=new _i(s.x,s.y,{format:lr,type:zi}):(T.mapPass.width!==T.map.width||T.mapPass.height!==T.map.height)&&T.mapPass.setSize(T.map.width,T.map.height),u.uniforms.shadow_pass.value=T.map.depthTexture,u.uniforms.resolution.value.set(T.map.width,T.map.height),u.uniforms.radius.value=T.radius,n.setRenderTarget(T.mapPass),n.clear(),n.renderBufferDirect(_,null,w,u,v,null),m.uniforms.shadow_pass.value=T.mapPass.texture,m.uniforms.resolution.value.set(T.map.width,T.map.height),m.uniforms.radius.value=T.radius,n.setRenderTarget(T.map),n.clear(),n.renderBufferDirect(_,null,w,m,v,null)}function A(T,_,w,U){let N=null,R=w.isPointLight===!0?T.customDistanceMaterial:T.customDepthMaterial;if(R!==void 0)N=R;else if(N=w.isPointLight===!0?l:a,n.localClippingEnabled&&_.clipShadows===!0&&Array.isArray(_.clippingPlanes)&&_.clippingPlanes.length!==0||_.displacementMap&&_.displacementScale!==0||_.alphaMap&&_.alphaTest>0||_.map&&_.alphaTest>0||_.alphaToCoverage===!0){let G=N.uuid,B=_.uuid,L=c[G];L===void 0&&(L={},c[G]=L);let z=L[B];z===void 0&&(z=N.clone(),L[B]=z,_.addEventListener("dispose",C)),N=z}if(N.visible=_.visible,N.wireframe=_.wireframe,U===Uo?N.side=_.shadowSide!==null?_.shadowSide:_.side:N.side=_.shadowSide!==null?_.shadowSide:f[_.side],N.alphaMap=_.alphaMap,N.alphaTest=_.alphaToCoverage===!0?.5:_.alphaTest,N.map=_.map,N.clipShadows=_.clipShadows,N.clippingPlanes=_.clippingPlanes,N.clipIntersection=_.clipIntersection,N.displacementMap=_.displacementMap,N.displacementScale=_.displacementScale,N.displacementBias=_.displacementBias,N.wireframeLinewidth=_.wireframeLinewidth,N.linewidth=_.linewidth,w.isPointLight===!0&&N.isMeshDistanceMaterial===!0){let G=n.properties.get(N);G.light=w}return N}function S(T,_,w,U,N,R){if(T.visible===!1)return;if(T.layers.test(N)&&(T.isMesh||T.isLine||T.isPoints)&&(T.castShadow||T.receiveShadow&&R===Uo)&&(!T.frustumCulled||T.intersectsFrustum(i))){T.modelViewMatrix.multiplyMatrices(w.matrixWorldInverse,T.matrixWorld);let L=e.update(T),z=T.material;if(Array.isArray(z)){let q=L.groups;for(let O=0,re=q.length;O<re;O++){let X=q[O],$=z[X.materialIndex];if($&&$.visible){let W=A(T,$,U,R);T.onBeforeShadow(n,T,_,w,L,W,X),n.renderBufferDirect(w,null,L,W,T,X),T.onAfterShadow(n,T,_,w,L,W,X)}}}else if(z.visible){let q=A(T,z,U,R);T.onBeforeShadow(n,T,_,w,L,q,null),n.renderBufferDirect(w,null,L,q,T,null),T.onAfterShadow(n,T,_,w,L,q,null)}}let B=T.children;for(let L=0,z=B.length;L<z;L++)S(B[L],_,w,U,N,R)}function C(T){T.target.removeEventListener("dispose",C);for(let w in c){let U=c[w],N=T.target.uuid;N in U&&(U[N].dispose(),delete U[N])}}}function XE(n,e){function t(){let k=!1,ae=new rn,se=null,Re=new rn(0,0,0,0);return{setMask:function(Se){se!==Se&&!k&&(n.colorMask(Se,Se,Se,Se),se=Se)},setLocked:function(Se){k=Se},setClear:function(Se,Te,$e,st,ue){ue===!0&&(Se*=st,Te*=st,$e*=st),ae.set(Se,Te,$e,st),Re.equals(ae)===!1&&(n.clearColor(Se,Te,$e,st),Re.copy(ae))},reset:function(){k=!1,se=null,Re.set(-1,0,0,0)}}}function i(){let k=!1,ae=!1,se=null,Re=null,Se=null;return{setReversed:function(Te){if(ae!==Te){let $e=e.get("EXT_clip_control");Te?$e.clipControlEXT($e.LOWER_LEFT_EXT,$e.ZERO_TO_ONE_EXT):$e.clipControlEXT($e.LOWER_LEFT_EXT,$e.NEGATIVE_ONE_TO_ONE_EXT),ae=Te;let st=Se;Se=null,this.setClear(st)}},getReversed:function(){return ae},setTest:function(Te){Te?xe(n.DEPTH_TEST):We(n.DEPTH_TEST)},setMask:function(Te){se!==Te&&!k&&(n.depthMask(Te),se=Te)},setFunc:function(Te){if(ae&&(Te=D0[Te]),Re!==Te){switch(Te){case xc:n.depthFunc(n.NEVER);break;case vc:n.depthFunc(n.ALWAYS);break;case bc:n.depthFunc(n.LESS);break;case Eo:n.depthFunc(n.LEQUAL);break;case Sc:n.depthFunc(n.EQUAL);break;case Mc:n.depthFunc(n.GEQUAL);break;case wc:n.depthFunc(n.GREATER);break;case Ec:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Re=Te}},setLocked:function(Te){k=Te},setClear:function(Te){Se!==Te&&(Se=Te,ae&&(Te=1-Te),n.clearDepth(Te))},reset:function(){k=!1,se=null,Re=null,Se=null,ae=!1}}}function s(){let k=!1,ae=null,se=null,Re=null,Se=null,Te=null,$e=null,st=null,ue=null;return{setTest:function(Ge){k||(Ge?xe(n.STENCIL_TEST):We(n.STENCIL_TEST))},setMask:function(Ge){ae!==Ge&&!k&&(n.stencilMask(Ge),ae=Ge)},setFunc:function(Ge,rt,Pe){(se!==Ge||Re!==rt||Se!==Pe)&&(n.stencilFunc(Ge,rt,Pe),se=Ge,Re=rt,Se=Pe)},setOp:function(Ge,rt,Pe){(Te!==Ge||$e!==rt||st!==Pe)&&(n.stencilOp(Ge,rt,Pe),Te=Ge,$e=rt,st=Pe)},setLocked:function(Ge){k=Ge},setClear:function(Ge){ue!==Ge&&(n.clearStencil(Ge),ue=Ge)},reset:function(){k=!1,ae=null,se=null,Re=null,Se=null,Te=null,$e=null,st=null,ue=null}}}let r=new t,o=new i,a=new s,l={},c=new WeakMap,h={},f={},u={},m=new WeakMap,g=[],v=null,d=!1,p=null,x=null,A=null,S=null,C=null,T=null,_=null,w=new _t(0,0,0),U=0,N=!1,R=null,G=null,B=null,L=null,z=null,q=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS),O=!1,re=0,X=n.getParameter(n.VERSION);X.indexOf("WebGL")!==-1?(re=parseFloat(/^WebGL (\d)/.exec(X)[1]),O=re>=1):X.indexOf("OpenGL ES")!==-1&&(re=parseFloat(/^OpenGL ES (\d)/.exec(X)[1]),O=re>=2);let $=null,W={},ne=n.getParameter(n.SCISSOR_BOX),le=n.getParameter(n.VIEWPORT),Q=new rn().fromArray(ne),me=new rn().fromArray(le);function pe(k,ae,se,Re){let Se=new Uint8Array(4),Te=n.createTexture();n.bindTexture(k,Te),n.texParameteri(k,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(k,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let $e=0;$e<se;$e++)k===n.TEXTURE_3D||k===n.TEXTURE_2D_ARRAY?n.texImage3D(ae,0,n.RGBA,1,1,Re,0,n.RGBA,n.UNSIGNED_BYTE,Se):n.texImage2D(ae+$e,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,Se);return Te}let be={};be[n.TEXTURE_2D]=pe(n.TEXTURE_2D,n.TEXTURE_2D,1),be[n.TEXTURE_CUBE_MAP]=pe(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),be[n.TEXTURE_2D_ARRAY]=pe(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),be[n.TEXTURE_3D]=pe(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),o.setClear(1),a.setClear(0),xe(n.DEPTH_TEST),o.setFunc(Eo),Rt(!1),wt(Lf),xe(n.CULL_FACE),ke(Pr);function xe(k){h[k]!==!0&&(n.enable(k),h[k]=!0)}function We(k){h[k]!==!1&&(n.disable(k),h[k]=!1)}function Qe(k,ae){return u[k]!==ae?(n.bindFramebuffer(k,ae),u[k]=ae,k===n.DRAW_FRAMEBUFFER&&(u[n.FRAMEBUFFER]=ae),k===n.FRAMEBUFFER&&(u[n.DRAW_FRAMEBUFFER]=ae),!0):!1}function Ne(k,ae){let se=g,Re=!1;if(k){se=m.get(ae),se===void 0&&(se=[],m.set(ae,se));let Se=k.textures;if(se.length!==Se.length||se[0]!==n.COLOR_ATTACHMENT0){for(let Te=0,$e=Se.length;Te<$e;Te++)se[Te]=n.COLOR_ATTACHMENT0+Te;se.length=Se.length,Re=!0}}else se[0]!==n.BACK&&(se[0]=n.BACK,Re=!0);Re&&n.drawBuffers(se)}function qe(k){return v!==k?(n.useProgram(k),v=k,!0):!1}let tt={[Lr]:n.FUNC_ADD,[n0]:n.FUNC_SUBTRACT,[i0]:n.FUNC_REVERSE_SUBTRACT};tt[s0]=n.MIN,tt[r0]=n.MAX;let fe={[o0]:n.ZERO,[a0]:n.ONE,[l0]:n.SRC_COLOR,[Of]:n.SRC_ALPHA,[p0]:n.SRC_ALPHA_SATURATE,[f0]:n.DST_COLOR,[h0]:n.DST_ALPHA,[c0]:n.ONE_MINUS_SRC_COLOR,[Ff]:n.ONE_MINUS_SRC_ALPHA,[d0]:n.ONE_MINUS_DST_COLOR,[u0]:n.ONE_MINUS_DST_ALPHA,[m0]:n.CONSTANT_COLOR,[g0]:n.ONE_MINUS_CONSTANT_COLOR,[_0]:n.CONSTANT_ALPHA,[y0]:n.ONE_MINUS_CONSTANT_ALPHA};function ke(k,ae,se,Re,Se,Te,$e,st,ue,Ge){if(k===Pr){d===!0&&(We(n.BLEND),d=!1);return}if(d===!1&&(xe(n.BLEND),d=!0),k!==t0){if(k!==p||Ge!==N){if((x!==Lr||C!==Lr)&&(n.blendEquation(n.FUNC_ADD),x=Lr,C=Lr),Ge)switch(k){case Oo:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Nf:n.blendFunc(n.ONE,n.ONE);break;case Df:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case Uf:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:at("WebGLState: Invalid blending: ",k);break}else switch(k){case Oo:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Nf:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case Df:at("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Uf:at("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:at("WebGLState: Invalid blending: ",k);break}A=null,S=null,T=null,_=null,w.set(0,0,0),U=0,p=k,N=Ge}return}Se=Se||ae,Te=Te||se,$e=$e||Re,(ae!==x||Se!==C)&&(n.blendEquationSeparate(tt[ae],tt[Se]),x=ae,C=Se),(se!==A||Re!==S||Te!==T||$e!==_)&&(n.blendFuncSeparate(fe[se],fe[Re],fe[Te],fe[$e]),A=se,S=Re,T=Te,_=$e),(st.equals(w)===!1||ue!==U)&&(n.blendColor(st.r,st.g,st.b,ue),w.copy(st),U=ue),p=k,N=!1}function Ze(k,ae){k.side===is?We(n.CULL_FACE):xe(n.CULL_FACE);let se=k.side===Kn;ae&&(se=!se),Rt(se),k.blending===Oo&&k.transparent===!1?ke(Pr):ke(k.blending,k.blendEquation,k.blendSrc,k.blendDst,k.blendEquationAlpha,k.blendSrcAlpha,k.blendDstAlpha,k.blendColor,k.blendAlpha,k.premultipliedAlpha),o.setFunc(k.depthFunc),o.setTest(k.depthTest),o.setMask(k.depthWrite),r.setMask(k.colorWrite);let Re=k.stencilWrite;a.setTest(Re),Re&&(a.setMask(k.stencilWriteMask),a.setFunc(k.stencilFunc,k.stencilRef,k.stencilFuncMask),a.setOp(k.stencilFail,k.stencilZFail,k.stencilZPass)),et(k.polygonOffset,k.polygonOffsetFactor,k.polygonOffsetUnits),k.alphaToCoverage===!0?xe(n.SAMPLE_ALPHA_TO_COVERAGE):We(n.SAMPLE_ALPHA_TO_COVERAGE)}function Rt(k){R!==k&&(k?n.frontFace(n.CW):n.frontFace(n.CCW),R=k)}function wt(k){k!==jg?(xe(n.CULL_FACE),k!==G&&(k===Lf?n.cullFace(n.BACK):k===Qg?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):We(n.CULL_FACE),G=k}function Vt(k){k!==B&&(O&&n.lineWidth(k),B=k)}function et(k,ae,se){k?(xe(n.POLYGON_OFFSET_FILL),(L!==ae||z!==se)&&(L=ae,z=se,o.getReversed()&&(ae=-ae,se=-se),n.polygonOffset(ae,se))):We(n.POLYGON_OFFSET_FILL)}function Ct(k){k?xe(n.SCISSOR_TEST):We(n.SCISSOR_TEST)}function ut(k){k===void 0&&(k=n.TEXTURE0+q-1),$!==k&&(n.activeTexture(k),$=k)}function ft(k,ae,se){se===void 0&&($===null?se=n.TEXTURE0+q-1:se=$);let Re=W[se];Re===void 0&&(Re={type:void 0,texture:void 0},W[se]=Re),(Re.type!==k||Re.texture!==ae)&&($!==se&&(n.activeTexture(se),$=se),n.bindTexture(k,ae||be[k]),Re.type=k,Re.texture=ae)}function F(){let k=W[$];k!==void 0&&k.type!==void 0&&(n.bindTexture(k.type,null),k.type=void 0,k.texture=void 0)}function ge(){try{n.compressedTexImage2D(...arguments)}catch(k){at("WebGLState:",k)}}function Ke(){try{n.compressedTexImage3D(...arguments)}catch(k){at("WebGLState:",k)}}function dt(){try{n.texSubImage2D(...arguments)}catch(k){at("WebGLState:",k)}}function Ae(){try{n.texSubImage3D(...arguments)}catch(k){at("WebGLState:",k)}}function Wt(){try{n.compressedTexSubImage2D(...arguments)}catch(k){at("WebGLState:",k)}}function Xe(){try{n.compressedTexSubImage3D(...arguments)}catch(k){at("WebGLState:",k)}}function Je(){try{n.texStorage2D(...arguments)}catch(k){at("WebGLState:",k)}}function I(){try{n.texStorage3D(...arguments)}catch(k){at("WebGLState:",k)}}function b(){try{n.texImage2D(...arguments)}catch(k){at("WebGLState:",k)}}function Y(){try{n.texImage3D(...arguments)}catch(k){at("WebGLState:",k)}}function de(k){return f[k]!==void 0?f[k]:n.getParameter(k)}function ce(k,ae){f[k]!==ae&&(n.pixelStorei(k,ae),f[k]=ae)}function Me(k){Q.equals(k)===!1&&(n.scissor(k.x,k.y,k.z,k.w),Q.copy(k))}function we(k){me.equals(k)===!1&&(n.viewport(k.x,k.y,k.z,k.w),me.copy(k))}function ie(k,ae){let se=c.get(ae);se===void 0&&(se=new WeakMap,c.set(ae,se));let Re=se.get(k);Re===void 0&&(Re=n.getUniformBlockIndex(ae,k.name),n.uniformBlockBinding(ae,Re,Re),se.set(k,Re))}function oe(k,ae,se){let Se=c.get(ae).get(k);l[Se]!==se&&(n.bindBufferBase(n.UNIFORM_BUFFER,Se,se),l[Se]=se)}function ye(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),o.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),h={},f={},$=null,W={},u={},l={},m=new WeakMap,g=[],v=null,d=!1,p=null,x=null,A=null,S=null,C=null,T=null,_=null,w=new _t(0,0,0),U=0,N=!1,R=null,G=null,B=null,L=null,z=null,Q.set(0,0,n.canvas.width,n.canvas.height),me.set(0,0,n.canvas.width,n.canvas.height),r.reset(),o.reset(),a.reset()}return{buffers:{color:r,depth:o,stencil:a},enable:xe,disable:We,bindFramebuffer:Qe,drawBuffers:Ne,useProgram:qe,setBlending:ke,setMaterial:Ze,setFlipSided:Rt,setCullFace:wt,setLineWidth:Vt,setPolygonOffset:et,setScissorTest:Ct,activeTexture:ut,bindTexture:ft,unbindTexture:F,compressedTexImage2D:ge,compressedTexImage3D:Ke,texImage2D:b,texImage3D:Y,pixelStorei:ce,getParameter:de,updateUBOMapping:ie,uniformBlockBinding:oe,texStorage2D:Je,texStorage3D:I,texSubImage2D:dt,texSubImage3D:Ae,compressedTexSubImage2D:Wt,compressedTexSubImage3D:Xe,scissor:Me,viewport:we,reset:ye}}function $E(n,e,t,i,s,r,o){let a=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new pt,h=new WeakMap,f=new Set,u,m=new WeakMap,g=new Set,v=new FinalizationRegistry(I=>g.delete(I)),d=!1;try{d=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function p(I,b){return d?new OffscreenCanvas(I,b):Aa("canvas")}function x(I,b,Y){let de=1,ce=Je(I);if((ce.width>Y||ce.height>Y)&&(de=Y/Math.max(ce.width,ce.height)),de<1)if(typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&I instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&I instanceof ImageBitmap||typeof VideoFrame<"u"&&I instanceof VideoFrame){let Me=Math.floor(de*ce.width),we=Math.floor(de*ce.height);u===void 0&&(u=p(Me,we));let ie=b?p(Me,we):u;return ie.width=Me,ie.height=we,ie.getContext("2d").drawImage(I,0,0,Me,we),je("WebGLRenderer: Texture has been resized from ("+ce.width+"x"+ce.height+") to ("+Me+"x"+we+")."),ie}else return"data"in I&&je("WebGLRenderer: Image in DataTexture is too big ("+ce.width+"x"+ce.height+")."),I;return I}function A(I){return I.generateMipmaps}function S(I){n.generateMipmap(I)}function C(I){return I.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:I.isWebGL3DRenderTarget?n.TEXTURE_3D:I.isWebGLArrayRenderTarget||I.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function T(I,b,Y,de,ce,Me=!1){if(I!==null){if(n[I]!==void 0)return n[I];je("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+I+"'")}let we;de&&(we=e.get("EXT_texture_norm16"),we||je("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let ie=b;if(b===n.RED&&(Y===n.FLOAT&&(ie=n.R32F),Y===n.HALF_FLOAT&&(ie=n.R16F),Y===n.UNSIGNED_BYTE&&(ie=n.R8),Y===n.UNSIGNED_SHORT&&we&&(ie=we.R16_EXT),Y===n.SHORT&&we&&(ie=we.R16_SNORM_EXT)),b===n.RED_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.R8UI),Y===n.UNSIGNED_SHORT&&(ie=n.R16UI),Y===n.UNSIGNED_INT&&(ie=n.R32UI),Y===n.BYTE&&(ie=n.R8I),Y===n.SHORT&&(ie=n.R16I),Y===n.INT&&(ie=n.R32I)),b===n.RG&&(Y===n.FLOAT&&(ie=n.RG32F),Y===n.HALF_FLOAT&&(ie=n.RG16F),Y===n.UNSIGNED_BYTE&&(ie=n.RG8),Y===n.UNSIGNED_SHORT&&we&&(ie=we.RG16_EXT),Y===n.SHORT&&we&&(ie=we.RG16_SNORM_EXT)),b===n.RG_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.RG8UI),Y===n.UNSIGNED_SHORT&&(ie=n.RG16UI),Y===n.UNSIGNED_INT&&(ie=n.RG32UI),Y===n.BYTE&&(ie=n.RG8I),Y===n.SHORT&&(ie=n.RG16I),Y===n.INT&&(ie=n.RG32I)),b===n.RGB_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.RGB8UI),Y===n.UNSIGNED_SHORT&&(ie=n.RGB16UI),Y===n.UNSIGNED_INT&&(ie=n.RGB32UI),Y===n.BYTE&&(ie=n.RGB8I),Y===n.SHORT&&(ie=n.RGB16I),Y===n.INT&&(ie=n.RGB32I)),b===n.RGBA_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ie=n.RGBA8UI),Y===n.UNSIGNED_SHORT&&(ie=n.RGBA16UI),Y===n.UNSIGNED_INT&&(ie=n.RGBA32UI),Y===n.BYTE&&(ie=n.RGBA8I),Y===n.SHORT&&(ie=n.RGBA16I),Y===n.INT&&(ie=n.RGBA32I)),b===n.RGB&&(Y===n.UNSIGNED_SHORT&&we&&(ie=we.RGB16_EXT),Y===n.SHORT&&we&&(ie=we.RGB16_SNORM_EXT),Y===n.UNSIGNED_INT_5_9_9_9_REV&&(ie=n.RGB9_E5),Y===n.UNSIGNED_INT_10F_11F_11F_REV&&(ie=n.R11F_G11F_B10F)),b===n.RGBA){let oe=Me?Ea:At.getTransfer(ce);Y===n.FLOAT&&(ie=n.RGBA32F),Y===n.HALF_FLOAT&&(ie=n.RGBA16F),Y===n.UNSIGNED_BYTE&&(ie=oe===Ft?n.SRGB8_ALPHA8:n.RGBA8),Y===n.UNSIGNED_SHORT&&we&&(ie=we.RGBA16_EXT),Y===n.SHORT&&we&&(ie=we.RGBA16_SNORM_EXT),Y===n.UNSIGNED_SHORT_4_4_4_4&&(ie=n.RGBA4),Y===n.UNSIGNED_SHORT_5_5_5_1&&(ie=n.RGB5_A1)}return(ie===n.R16F||ie===n.R32F||ie===n.RG16F||ie===n.RG32F||ie===n.RGBA16F||ie===n.RGBA32F)&&e.get("EXT_color_buffer_float"),ie}function _(I,b){let Y;return I?b===null||b===Bi||b===Dr?Y=n.DEPTH24_STENCIL8:b===ki?Y=n.DEPTH32F_STENCIL8:b===Bo&&(Y=n.DEPTH24_STENCIL8,je("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):b===null||b===Bi||b===Dr?Y=n.DEPTH_COMPONENT24:b===ki?Y=n.DEPTH_COMPONENT32F:b===Bo&&(Y=n.DEPTH_COMPONENT16),Y}function w(I,b){return A(I)===!0||I.isFramebufferTexture&&I.minFilter!==Dn&&I.minFilter!==Zn?Math.log2(Math.max(b.width,b.height))+1:I.mipmaps.length>0?I.mipmaps.length:I.isCompressedTexture&&Array.isArray(I.image)?b.mipmaps.length:1}function U(I){let b=new WeakRef(I);i.get(I).__ref=b,g.add(b),v.register(I,b,b)}function N(I){let b=i.get(I).__ref;b!==void 0&&(g.delete(b),v.unregister(b))}function R(I){B(I.target)}function G(I){L(I.target)}function B(I){I.removeEventListener("dispose",R),N(I),q(I),I.isVideoTexture&&h.delete(I),I.isHTMLTexture&&f.delete(I)}function L(I){I.removeEventListener("dispose",G),N(I),re(I)}function z(){for(let I of g){let b=I.deref();b!==void 0&&(b.isRenderTarget===!0?L(b):B(b))}g.clear(),f.clear()}function q(I){let b=i.get(I);if(b.__webglInit===void 0)return;let Y=I.source,de=m.get(Y);if(de){let ce=de[b.__cacheKey];ce.usedTimes--,ce.usedTimes===0&&O(I),Object.keys(de).length===0&&m.delete(Y)}i.remove(I)}function O(I){let b=i.get(I);n.deleteTexture(b.__webglTexture);let Y=I.source,de=m.get(Y);delete de[b.__cacheKey],o.memory.textures--}function re(I){let b=i.get(I);b.__depthDisposeCallback&&b.__depthDisposeCallback();let Y=I.depthTexture;if(Y&&Y.renderTarget===I&&B(Y),I.isWebGLCubeRenderTarget)for(let ce=0;ce<6;ce++){if(Array.isArray(b.__webglFramebuffer[ce]))for(let Me=0;Me<b.__webglFramebuffer[ce].length;Me++)n.deleteFramebuffer(b.__webglFramebuffer[ce][Me]);else n.deleteFramebuffer(b.__webglFramebuffer[ce]);b.__webglDepthbuffer&&n.deleteRenderbuffer(b.__webglDepthbuffer[ce])}else{if(Array.isArray(b.__webglFramebuffer))for(let ce=0;ce<b.__webglFramebuffer.length;ce++)n.deleteFramebuffer(b.__webglFramebuffer[ce]);else n.deleteFramebuffer(b.__webglFramebuffer);if(b.__webglDepthbuffer&&n.deleteRenderbuffer(b.__webglDepthbuffer),b.__webglMultisampledFramebuffer&&n.deleteFramebuffer(b.__webglMultisampledFramebuffer),b.__webglColorRenderbuffer)for(let ce=0;ce<b.__webglColorRenderbuffer.length;ce++)b.__webglColorRenderbuffer[ce]&&n.deleteRenderbuffer(b.__webglColorRenderbuffer[ce]);b.__webglDepthRenderbuffer&&n.deleteRenderbuffer(b.__webglDepthRenderbuffer)}let de=I.textures;for(let ce=0,Me=de.length;ce<Me;ce++){let we=i.get(de[ce]);we.__webglTexture&&(n.deleteTexture(we.__webglTexture),o.memory.textures--),i.remove(de[ce])}i.remove(I)}let X=0;function $(){X=0}function W(){return X}function ne(I){X=I}function le(){let I=X;return I>=s.maxTextures&&je("WebGLTextures: Trying to use "+(I+1)+" texture units while this GPU supports only "+s.maxTextures),X+=1,I}function Q(I){let b=[];return b.push(I.wrapS),b.push(I.wrapT),b.push(I.wrapR||0),b.push(I.magFilter),b.push(I.minFilter),b.push(I.anisotropy),b.push(I.internalFormat),b.push(I.format),b.push(I.type),b.push(I.generateMipmaps),b.push(I.mipmapsAutoUpdate),b.push(I.premultiplyAlpha),b.push(I.flipY),b.push(I.unpackAlignment),b.push(I.colorSpace),b.join()}function me(I,b){let Y=i.get(I);if(I.isVideoTexture&&Wt(I),I.isRenderTargetTexture===!1&&I.isExternalTexture!==!0&&I.version>0&&Y.__version!==I.version){let de=I.image;if(de===null)je("WebGLRenderer: Texture marked for update but no image data found.");else if(de.complete===!1)je("WebGLRenderer: Texture marked for update but image is incomplete");else{Ze(Y,I,b);return}}else I.isExternalTexture&&(Y.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D,Y.__webglTexture,n.TEXTURE0+b)}function pe(I,b){let Y=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&Y.__version!==I.version){Ze(Y,I,b);return}else I.isExternalTexture&&(Y.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D_ARRAY,Y.__webglTexture,n.TEXTURE0+b)}function be(I,b){let Y=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&Y.__version!==I.version){Ze(Y,I,b);return}t.bindTexture(n.TEXTURE_3D,Y.__webglTexture,n.TEXTURE0+b)}function xe(I,b){let Y=i.get(I);if(I.version>0&&Y.__version!==I.version){Rt(Y,I,b);return}t.bindTexture(n.TEXTURE_CUBE_MAP,Y.__webglTexture,n.TEXTURE0+b)}let We={[Tc]:n.REPEAT,[es]:n.CLAMP_TO_EDGE,[Ac]:n.MIRRORED_REPEAT},Qe={[Dn]:n.NEAREST,[b0]:n.NEAREST_MIPMAP_NEAREST,[Xa]:n.NEAREST_MIPMAP_LINEAR,[Zn]:n.LINEAR,[nh]:n.LINEAR_MIPMAP_NEAREST,[Ts]:n.LINEAR_MIPMAP_LINEAR},Ne={[E0]:n.NEVER,[id]:n.ALWAYS,[T0]:n.LESS,[td]:n.LEQUAL,[A0]:n.EQUAL,[nd]:n.GEQUAL,[R0]:n.GREATER,[C0]:n.NOTEQUAL};function qe(I,b){if(b.type===ki&&e.has("OES_texture_float_linear")===!1&&(b.magFilter===Zn||b.magFilter===nh||b.magFilter===Xa||b.magFilter===Ts||b.minFilter===Zn||b.minFilter===nh||b.minFilter===Xa||b.minFilter===Ts)&&je("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(I,n.TEXTURE_WRAP_S,We[b.wrapS]),n.texParameteri(I,n.TEXTURE_WRAP_T,We[b.wrapT]),(I===n.TEXTURE_3D||I===n.TEXTURE_2D_ARRAY)&&n.texParameteri(I,n.TEXTURE_WRAP_R,We[b.wrapR]),n.texParameteri(I,n.TEXTURE_MAG_FILTER,Qe[b.magFilter]),n.texParameteri(I,n.TEXTURE_MIN_FILTER,Qe[b.minFilter]),b.compareFunction&&(n.texParameteri(I,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(I,n.TEXTURE_COMPARE_FUNC,Ne[b.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(b.magFilter===Dn||b.minFilter!==Xa&&b.minFilter!==Ts||b.type===ki&&e.has("OES_texture_float_linear")===!1)return;if(b.anisotropy>1||i.get(b).__currentAnisotropy){let Y=e.get("EXT_texture_filter_anisotropic");n.texParameterf(I,Y.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(b.anisotropy,s.getMaxAnisotropy())),i.get(b).__currentAnisotropy=b.anisotropy}}}function tt(I,b){let Y=!1;I.__webglInit===void 0&&(I.__webglInit=!0,b.addEventListener("dispose",R),U(b));let de=b.source,ce=m.get(de);ce===void 0&&(ce={},m.set(de,ce));let Me=Q(b);if(Me!==I.__cacheKey){ce[Me]===void 0&&(ce[Me]={texture:n.createTexture(),usedTimes:0},o.memory.textures++,Y=!0),ce[Me].usedTimes++;let we=ce[I.__cacheKey];we!==void 0&&(ce[I.__cacheKey].usedTimes--,we.usedTimes===0&&O(b)),I.__cacheKey=Me,I.__webglTexture=ce[Me].texture}return Y}function fe(I,b,Y){return Math.floor(Math.floor(I/Y)/b)}function ke(I,b,Y,de){let Me=I.updateRanges;if(Me.length===0)t.texSubImage2D(n.TEXTURE_2D,0,0,0,b.width,b.height,Y,de,b.data);else{Me.sort((k,ae)=>k.start-ae.start);let we=0;for(let k=1;k<Me.length;k++){let ae=Me[we],se=Me[k],Re=ae.start+ae.count,Se=fe(se.start,b.width,4),Te=fe(ae.start,b.width,4);se.start<=Re+1&&Se===Te&&fe(se.start+se.count-1,b.width,4)===Se?ae.count=Math.max(ae.count,se.start+se.count-ae.start):(++we,Me[we]=se)}Me.length=we+1;let ie=t.getParameter(n.UNPACK_ROW_LENGTH),oe=t.getParameter(n.UNPACK_SKIP_PIXELS),ye=t.getParameter(n.UNPACK_SKIP_ROWS);t.pixelStorei(n.UNPACK_ROW_LENGTH,b.width);for(let k=0,ae=Me.length;k<ae;k++){let se=Me[k],Re=Math.floor(se.start/4),Se=Math.ceil(se.count/4),Te=Re%b.width,$e=Math.floor(Re/b.width),st=Se,ue=1;t.pixelStorei(n.UNPACK_SKIP_PIXELS,Te),t.pixelStorei(n.UNPACK_SKIP_ROWS,$e),t.texSubImage2D(n.TEXTURE_2D,0,Te,$e,st,ue,Y,de,b.data)}I.clearUpdateRanges(),t.pixelStorei(n.UNPACK_ROW_LENGTH,ie),t.pixelStorei(n.UNPACK_SKIP_PIXELS,oe),t.pixelStorei(n.UNPACK_SKIP_ROWS,ye)}}function Ze(I,b,Y){let de=n.TEXTURE_2D;(b.isDataArrayTexture||b.isCompressedArrayTexture)&&(de=n.TEXTURE_2D_ARRAY),b.isData3DTexture&&(de=n.TEXTURE_3D);let ce=tt(I,b),Me=b.source;t.bindTexture(de,I.__webglTexture,n.TEXTURE0+Y);let we=i.get(Me);if(Me.version!==we.__version||ce===!0){if(t.activeTexture(n.TEXTURE0+Y),(typeof ImageBitmap<"u"&&b.image instanceof ImageBitmap)===!1){let ue=At.getPrimaries(At.workingColorSpace),Ge=b.colorSpace===Rs?null:At.getPrimaries(b.colorSpace),rt=b.colorSpace===Rs||ue===Ge?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,b.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,b.premultiplyAlpha),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,rt)}t.pixelStorei(n.UNPACK_ALIGNMENT,b.unpackAlignment);let oe=x(b.image,!1,s.maxTextureSize);oe=Xe(b,oe);let ye=r.convert(b.format,b.colorSpace),k=r.convert(b.type),ae=T(b.internalFormat,ye,k,b.normalized,b.colorSpace,b.isVideoTexture);qe(de,b);let se,Re=b.mipmaps,Se=b.isVideoTexture!==!0,Te=we.__version===void 0||ce===!0,$e=Me.dataReady,st=w(b,oe);if(b.isDepthTexture)ae=_(b.format===As,b.type),Te&&(Se?t.texStorage2D(n.TEXTURE_2D,1,ae,oe.width,oe.height):t.texImage2D(n.TEXTURE_2D,0,ae,oe.width,oe.height,0,ye,k,null));else if(b.isDataTexture)if(Re.length>0){Se&&Te&&t.texStorage2D(n.TEXTURE_2D,st,ae,Re[0].width,Re[0].height);for(let ue=0,Ge=Re.length;ue<Ge;ue++)se=Re[ue],Se?$e&&t.texSubImage2D(n.TEXTURE_2D,ue,0,0,se.width,se.height,ye,k,se.data):t.texImage2D(n.TEXTURE_2D,ue,ae,se.width,se.height,0,ye,k,se.data);b.generateMipmaps=!1}else Se?(Te&&t.texStorage2D(n.TEXTURE_2D,st,ae,oe.width,oe.height),$e&&ke(b,oe,ye,k)):t.texImage2D(n.TEXTURE_2D,0,ae,oe.width,oe.height,0,ye,k,oe.data);else if(b.isCompressedTexture)if(b.isCompressedArrayTexture){Se&&Te&&t.texStorage3D(n.TEXTURE_2D_ARRAY,st,ae,Re[0].width,Re[0].height,oe.depth);for(let ue=0,Ge=Re.length;ue<Ge;ue++)if(se=Re[ue],b.format!==Gi)if(ye!==null)if(Se){if($e)if(b.layerUpdates.size>0){let rt=dd(se.width,se.height,b.format,b.type);for(let Pe of b.layerUpdates){let mt=se.data.subarray(Pe*rt/se.data.BYTES_PER_ELEMENT,(Pe+1)*rt/se.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ue,0,0,Pe,se.width,se.height,1,ye,mt)}}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ue,0,0,0,se.width,se.height,oe.depth,ye,se.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,ue,ae,se.width,se.height,oe.depth,0,se.data,0,0);else je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else Se?$e&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,ue,0,0,0,se.width,se.height,oe.depth,ye,k,se.data):t.texImage3D(n.TEXTURE_2D_ARRAY,ue,ae,se.width,se.height,oe.depth,0,ye,k,se.data);b.layerUpdates.size>0&&b.clearLayerUpdates()}else{Se&&Te&&t.texStorage2D(n.TEXTURE_2D,st,ae,Re[0].width,Re[0].height);for(let ue=0,Ge=Re.length;ue<Ge;ue++)se=Re[ue],b.format!==Gi?ye!==null?Se?$e&&t.compressedTexSubImage2D(n.TEXTURE_2D,ue,0,0,se.width,se.height,ye,se.data):t.compressedTexImage2D(n.TEXTURE_2D,ue,ae,se.width,se.height,0,se.data):je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):Se?$e&&t.texSubImage2D(n.TEXTURE_2D,ue,0,0,se.width,se.height,ye,k,se.data):t.texImage2D(n.TEXTURE_2D,ue,ae,se.width,se.height,0,ye,k,se.data)}else if(b.isDataArrayTexture)if(Se){if(Te&&t.texStorage3D(n.TEXTURE_2D_ARRAY,st,ae,oe.width,oe.height,oe.depth),$e)if(b.layerUpdates.size>0){let ue=dd(oe.width,oe.height,b.format,b.type);for(let Ge of b.layerUpdates){let rt=oe.data.subarray(Ge*ue/oe.data.BYTES_PER_ELEMENT,(Ge+1)*ue/oe.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,Ge,oe.width,oe.height,1,ye,k,rt)}b.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,oe.width,oe.height,oe.depth,ye,k,oe.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,ae,oe.width,oe.height,oe.depth,0,ye,k,oe.data);else if(b.isData3DTexture)Se?(Te&&t.texStorage3D(n.TEXTURE_3D,st,ae,oe.width,oe.height,oe.depth),$e&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,oe.width,oe.height,oe.depth,ye,k,oe.data)):t.texImage3D(n.TEXTURE_3D,0,ae,oe.width,oe.height,oe.depth,0,ye,k,oe.data);else if(b.isFramebufferTexture){if(Te)if(Se)t.texStorage2D(n.TEXTURE_2D,st,ae,oe.width,oe.height);else{let ue=oe.width,Ge=oe.height;for(let rt=0;rt<st;rt++)t.texImage2D(n.TEXTURE_2D,rt,ae,ue,Ge,0,ye,k,null),ue>>=1,Ge>>=1}}else if(b.isHTMLTexture){if("texElementImage2D"in n){let ue=n.canvas;if(ue.hasAttribute("layoutsubtree")||ue.setAttribute("layoutsubtree","true"),oe.parentNode!==ue){ue.appendChild(oe),f.add(b),ue.onpaint=Ge=>{let rt=Ge.changedElements;for(let Pe of f)rt.includes(Pe.image)&&(Pe.needsUpdate=!0)},ue.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,oe);else{let rt=n.RGBA,Pe=n.RGBA,mt=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,rt,Pe,mt,oe)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Re.length>0){if(Se&&Te){let ue=Je(Re[0]);t.texStorage2D(n.TEXTURE_2D,st,ae,ue.width,ue.height)}for(let ue=0,Ge=Re.length;ue<Ge;ue++)se=Re[ue],Se?$e&&t.texSubImage2D(n.TEXTURE_2D,ue,0,0,ye,k,se):t.texImage2D(n.TEXTURE_2D,ue,ae,ye,k,se);b.generateMipmaps=!1}else if(Se){if(Te){let ue=Je(oe);t.texStorage2D(n.TEXTURE_2D,st,ae,ue.width,ue.height)}$e&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,ye,k,oe)}else t.texImage2D(n.TEXTURE_2D,0,ae,ye,k,oe);A(b)&&b.mipmapsAutoUpdate===!0&&S(de),we.__version=Me.version,b.onUpdate&&b.onUpdate(b)}I.__version=b.version}function Rt(I,b,Y){if(b.image.length!==6)return;let de=tt(I,b),ce=b.source;t.bindTexture(n.TEXTURE_CUBE_MAP,I.__webglTexture,n.TEXTURE0+Y);let Me=i.get(ce);if(ce.version!==Me.__version||de===!0){t.activeTexture(n.TEXTURE0+Y);let we=At.getPrimaries(At.workingColorSpace),ie=b.colorSpace===Rs?null:At.getPrimaries(b.colorSpace),oe=b.colorSpace===Rs||we===ie?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,b.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,b.premultiplyAlpha),t.pixelStorei(n.UNPACK_ALIGNMENT,b.unpackAlignment),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,oe);let ye=b.isCompressedTexture||b.image[0].isCompressedTexture,k=b.image[0]&&b.image[0].isDataTexture,ae=[];for(let Pe=0;Pe<6;Pe++)!ye&&!k?ae[Pe]=x(b.image[Pe],!0,s.maxCubemapSize):ae[Pe]=k?b.image[Pe].image:b.image[Pe],ae[Pe]=Xe(b,ae[Pe]);let se=ae[0],Re=r.convert(b.format,b.colorSpace),Se=r.convert(b.type),Te=T(b.internalFormat,Re,Se,b.normalized,b.colorSpace),$e=b.isVideoTexture!==!0,st=Me.__version===void 0||de===!0,ue=ce.dataReady,Ge=w(b,se);qe(n.TEXTURE_CUBE_MAP,b);let rt;if(b.isDepthTexture){if(Te=_(b.format===As,b.type),st)if($e)t.texStorage2D(n.TEXTURE_CUBE_MAP,1,Te,se.width,se.height);else for(let Pe=0;Pe<6;Pe++)t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,Te,se.width,se.height,0,Re,Se,null)}else if(ye){$e&&st&&t.texStorage2D(n.TEXTURE_CUBE_MAP,Ge,Te,se.width,se.height);for(let Pe=0;Pe<6;Pe++){rt=ae[Pe].mipmaps;for(let mt=0;mt<rt.length;mt++){let qt=rt[mt];b.format!==Gi?Re!==null?$e?ue&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt,0,0,qt.width,qt.height,Re,qt.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt,Te,qt.width,qt.height,0,qt.data):je("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt,0,0,qt.width,qt.height,Re,Se,qt.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt,Te,qt.width,qt.height,0,Re,Se,qt.data)}}}else{if(rt=b.mipmaps,$e&&st){rt.length>0&&Ge++;let Pe=Je(ae[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,Ge,Te,Pe.width,Pe.height)}for(let Pe=0;Pe<6;Pe++)if(k){$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,0,0,ae[Pe].width,ae[Pe].height,Re,Se,ae[Pe].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,Te,ae[Pe].width,ae[Pe].height,0,Re,Se,ae[Pe].data);for(let mt=0;mt<rt.length;mt++){let Hn=rt[mt].image[Pe].image;$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt+1,0,0,Hn.width,Hn.height,Re,Se,Hn.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt+1,Te,Hn.width,Hn.height,0,Re,Se,Hn.data)}}else{$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,0,0,Re,Se,ae[Pe]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,0,Te,Re,Se,ae[Pe]);for(let mt=0;mt<rt.length;mt++){let qt=rt[mt];$e?ue&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt+1,0,0,Re,Se,qt.image[Pe]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Pe,mt+1,Te,Re,Se,qt.image[Pe])}}}A(b)&&b.mipmapsAutoUpdate===!0&&S(n.TEXTURE_CUBE_MAP),Me.__version=ce.version,b.onUpdate&&b.onUpdate(b)}I.__version=b.version}function wt(I,b,Y,de,ce,Me){let we=r.convert(Y.format,Y.colorSpace),ie=r.convert(Y.type),oe=T(Y.internalFormat,we,ie,Y.normalized,Y.colorSpace),ye=i.get(b),k=i.get(Y);if(k.__renderTarget=b,!ye.__hasExternalTextures){let ae=Math.max(1,b.width>>Me),se=Math.max(1,b.height>>Me);ce===n.TEXTURE_3D||ce===n.TEXTURE_2D_ARRAY?t.texImage3D(ce,Me,oe,ae,se,b.depth,0,we,ie,null):t.texImage2D(ce,Me,oe,ae,se,0,we,ie,null)}t.bindFramebuffer(n.FRAMEBUFFER,I),Ae(b)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,de,ce,k.__webglTexture,0,dt(b)):(ce===n.TEXTURE_2D||ce>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&ce<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,de,ce,k.__webglTexture,Me),t.bindFramebuffer(n.FRAMEBUFFER,null)}function Vt(I,b,Y){if(n.bindRenderbuffer(n.RENDERBUFFER,I),b.depthBuffer){let de=b.depthTexture,ce=de&&de.isDepthTexture?de.type:null,Me=_(b.stencilBuffer,ce),we=b.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;Ae(b)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,dt(b),Me,b.width,b.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,dt(b),Me,b.width,b.height):n.renderbufferStorage(n.RENDERBUFFER,Me,b.width,b.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,we,n.RENDERBUFFER,I)}else{let de=b.textures;for(let ce=0;ce<de.length;ce++){let Me=de[ce],we=r.convert(Me.format,Me.colorSpace),ie=r.convert(Me.type),oe=T(Me.internalFormat,we,ie,Me.normalized,Me.colorSpace);Ae(b)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,dt(b),oe,b.width,b.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,dt(b),oe,b.width,b.height):n.renderbufferStorage(n.RENDERBUFFER,oe,b.width,b.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function et(I,b,Y){let de=b.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(n.FRAMEBUFFER,I),!(b.depthTexture&&b.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let ce=i.get(b.depthTexture);ce.__renderTarget=b;let Me=de?b.depthTexture.image[0]:b.depthTexture.image;(!ce.__webglTexture||Me.width!==b.width||Me.height!==b.height)&&(Me.width=b.width,Me.height=b.height,b.depthTexture.needsUpdate=!0),de?xe(b.depthTexture,0):me(b.depthTexture,0);let we=ce.__webglTexture,ie=dt(b),oe=de?n.TEXTURE_CUBE_MAP_POSITIVE_X+Y:n.TEXTURE_2D,ye=b.depthTexture.format===As?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(b.depthTexture.format===Ms)Ae(b)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ye,oe,we,0,ie):n.framebufferTexture2D(n.FRAMEBUFFER,ye,oe,we,0);else if(b.depthTexture.format===As)Ae(b)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ye,oe,we,0,ie):n.framebufferTexture2D(n.FRAMEBUFFER,ye,oe,we,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function Ct(I){let b=i.get(I),Y=I.isWebGLCubeRenderTarget===!0;if(b.__boundDepthTexture!==I.depthTexture){let de=I.depthTexture;if(b.__depthDisposeCallback&&b.__depthDisposeCallback(),de){let ce=()=>{delete b.__boundDepthTexture,delete b.__depthDisposeCallback,de.removeEventListener("dispose",ce)};de.addEventListener("dispose",ce),b.__depthDisposeCallback=ce}b.__boundDepthTexture=de}if(I.depthTexture&&!b.__autoAllocateDepthBuffer)if(Y)for(let de=0;de<6;de++)et(b.__webglFramebuffer[de],I,de);else I.texture.mipmaps.length>0?et(b.__webglFramebuffer[0],I,0):et(b.__webglFramebuffer,I,0);else if(Y){b.__webglDepthbuffer=[];for(let de=0;de<6;de++)if(t.bindFramebuffer(n.FRAMEBUFFER,b.__webglFramebuffer[de]),b.__webglDepthbuffer[de]===void 0)b.__webglDepthbuffer[de]=n.createRenderbuffer(),Vt(b.__webglDepthbuffer[de],I,!1);else{let ce=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Me=b.__webglDepthbuffer[de];n.bindRenderbuffer(n.RENDERBUFFER,Me),n.framebufferRenderbuffer(n.FRAMEBUFFER,ce,n.RENDERBUFFER,Me)}}else if(I.texture.mipmaps.length>0?t.bindFramebuffer(n.FRAMEBUFFER,b.__webglFramebuffer[0]):t.bindFramebuffer(n.FRAMEBUFFER,b.__webglFramebuffer),b.__webglDepthbuffer===void 0)b.__webglDepthbuffer=n.createRenderbuffer(),Vt(b.__webglDepthbuffer,I,!1);else{let ce=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Me=b.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,Me),n.framebufferRenderbuffer(n.FRAMEBUFFER,ce,n.RENDERBUFFER,Me)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function ut(I,b,Y){let de=i.get(I);b!==void 0&&wt(de.__webglFramebuffer,I,I.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),Y!==void 0&&Ct(I)}function ft(I){let b=I.texture,Y=i.get(I),de=i.get(b);I.addEventListener("dispose",G),U(I);let ce=I.textures,Me=I.isWebGLCubeRenderTarget===!0,we=ce.length>1;if(we||(de.__webglTexture===void 0&&(de.__webglTexture=n.createTexture()),de.__version=b.version,o.memory.textures++),Me){Y.__webglFramebuffer=[];for(let ie=0;ie<6;ie++)if(b.mipmaps.length>0){Y.__webglFramebuffer[ie]=[];for(let oe=0;oe<b.mipmaps.length;oe++)Y.__webglFramebuffer[ie][oe]=n.createFramebuffer()}else Y.__webglFramebuffer[ie]=n.createFramebuffer()}else{if(b.mipmaps.length>0){Y.__webglFramebuffer=[];for(let ie=0;ie<b.mipmaps.length;ie++)Y.__webglFramebuffer[ie]=n.createFramebuffer()}else Y.__webglFramebuffer=n.createFramebuffer();if(we)for(let ie=0,oe=ce.length;ie<oe;ie++){let ye=i.get(ce[ie]);ye.__webglTexture===void 0&&(ye.__webglTexture=n.createTexture(),o.memory.textures++)}if(I.samples>0&&Ae(I)===!1){Y.__webglMultisampledFramebuffer=n.createFramebuffer(),Y.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,Y.__webglMultisampledFramebuffer);for(let ie=0;ie<ce.length;ie++){let oe=ce[ie];Y.__webglColorRenderbuffer[ie]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,Y.__webglColorRenderbuffer[ie]);let ye=r.convert(oe.format,oe.colorSpace),k=r.convert(oe.type),ae=T(oe.internalFormat,ye,k,oe.normalized,oe.colorSpace,I.isXRRenderTarget===!0),se=dt(I);n.renderbufferStorageMultisample(n.RENDERBUFFER,se,ae,I.width,I.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ie,n.RENDERBUFFER,Y.__webglColorRenderbuffer[ie])}n.bindRenderbuffer(n.RENDERBUFFER,null),I.depthBuffer&&(Y.__webglDepthRenderbuffer=n.createRenderbuffer(),Vt(Y.__webglDepthRenderbuffer,I,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(Me){t.bindTexture(n.TEXTURE_CUBE_MAP,de.__webglTexture),qe(n.TEXTURE_CUBE_MAP,b);for(let ie=0;ie<6;ie++)if(b.mipmaps.length>0)for(let oe=0;oe<b.mipmaps.length;oe++)wt(Y.__webglFramebuffer[ie][oe],I,b,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ie,oe);else wt(Y.__webglFramebuffer[ie],I,b,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ie,0);A(b)?S(n.TEXTURE_CUBE_MAP):b.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,b.mipmaps.length-1),t.unbindTexture()}else if(we){for(let ie=0,oe=ce.length;ie<oe;ie++){let ye=ce[ie],k=i.get(ye),ae=n.TEXTURE_2D;(I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(ae=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ae,k.__webglTexture),qe(ae,ye),wt(Y.__webglFramebuffer,I,ye,n.COLOR_ATTACHMENT0+ie,ae,0),A(ye)&&S(ae)}t.unbindTexture()}else{let ie=n.TEXTURE_2D;if((I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(ie=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ie,de.__webglTexture),qe(ie,b),b.mipmaps.length>0)for(let oe=0;oe<b.mipmaps.length;oe++)wt(Y.__webglFramebuffer[oe],I,b,n.COLOR_ATTACHMENT0,ie,oe);else wt(Y.__webglFramebuffer,I,b,n.COLOR_ATTACHMENT0,ie,0);A(b)?S(ie):b.mipmaps.length>0&&n.texParameteri(ie,n.TEXTURE_MAX_LEVEL,b.mipmaps.length-1),t.unbindTexture()}I.depthBuffer&&Ct(I)}function F(I){let b=I.textures;for(let Y=0,de=b.length;Y<de;Y++){let ce=b[Y];if(A(ce)&&ce.mipmapsAutoUpdate===!0){let Me=C(I),we=i.get(ce).__webglTexture;t.bindTexture(Me,we),S(Me),t.unbindTexture()}}}let ge=[];function Ke(I){if(I.samples>0){if(Ae(I)===!1){let b=I.textures,Y=I.width,de=I.height,ce=n.COLOR_BUFFER_BIT,Me=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,we=i.get(I),ie=b.length>1;if(ie)for(let ye=0;ye<b.length;ye++)t.bindFramebuffer(n.FRAMEBUFFER,we.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ye,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,we.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+ye,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,we.__webglMultisampledFramebuffer),I.texture.mipmaps.length>0?t.bindFramebuffer(n.DRAW_FRAMEBUFFER,we.__webglFramebuffer[0]):t.bindFramebuffer(n.DRAW_FRAMEBUFFER,we.__webglFramebuffer);for(let ye=0;ye<b.length;ye++){if(I.resolveDepthBuffer&&(I.depthBuffer&&(ce|=n.DEPTH_BUFFER_BIT),I.stencilBuffer&&I.resolveStencilBuffer&&(ce|=n.STENCIL_BUFFER_BIT)),ie){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,we.__webglColorRenderbuffer[ye]);let k=i.get(b[ye]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,k,0)}n.blitFramebuffer(0,0,Y,de,0,0,Y,de,ce,n.NEAREST),l===!0&&(ge.length=0,ge.push(n.COLOR_ATTACHMENT0+ye),I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&ge.push(Me),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,ge))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),ie)for(let ye=0;ye<b.length;ye++){t.bindFramebuffer(n.FRAMEBUFFER,we.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ye,n.RENDERBUFFER,we.__webglColorRenderbuffer[ye]);let k=i.get(b[ye]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,we.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+ye,n.TEXTURE_2D,k,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,we.__webglMultisampledFramebuffer)}else if(I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&l){let b=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[b])}}}function dt(I){return Math.min(s.maxSamples,I.samples)}function Ae(I){let b=i.get(I);return I.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&b.__useRenderToTexture!==!1}function Wt(I){let b=o.render.frame;h.get(I)!==b&&(h.set(I,b),I.update())}function Xe(I,b){let Y=I.colorSpace,de=I.format,ce=I.type;return I.isCompressedTexture===!0||I.isVideoTexture===!0||Y!==wa&&Y!==Rs&&(At.getTransfer(Y)===Ft?(de!==Gi||ce!==xi)&&je("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):at("WebGLTextures: Unsupported texture color space:",Y)),b}function Je(I){return typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement?(c.width=I.naturalWidth||I.width,c.height=I.naturalHeight||I.height):typeof VideoFrame<"u"&&I instanceof VideoFrame?(c.width=I.displayWidth,c.height=I.displayHeight):(c.width=I.width,c.height=I.height),c}this.allocateTextureUnit=le,this.resetTextureUnits=$,this.getTextureUnits=W,this.setTextureUnits=ne,this.setTexture2D=me,this.setTexture2DArray=pe,this.setTexture3D=be,this.setTextureCube=xe,this.rebindTextures=ut,this.setupRenderTarget=ft,this.updateRenderTargetMipmap=F,this.updateMultisampleRenderTarget=Ke,this.setupDepthRenderbuffer=Ct,this.setupFrameBufferTexture=wt,this.useMultisampledRTT=Ae,this.dispose=z}function qE(n,e){function t(i,s=Rs){let r,o=At.getTransfer(s);if(i===xi)return n.UNSIGNED_BYTE;if(i===sh)return n.UNSIGNED_SHORT_4_4_4_4;if(i===rh)return n.UNSIGNED_SHORT_5_5_5_1;if(i===Zf)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===Kf)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===qf)return n.BYTE;if(i===Yf)return n.SHORT;if(i===Bo)return n.UNSIGNED_SHORT;if(i===ih)return n.INT;if(i===Bi)return n.UNSIGNED_INT;if(i===ki)return n.FLOAT;if(i===zi)return n.HALF_FLOAT;if(i===Jf)return n.ALPHA;if(i===jf)return n.RGB;if(i===Gi)return n.RGBA;if(i===Ms)return n.DEPTH_COMPONENT;if(i===As)return n.DEPTH_STENCIL;if(i===Qf)return n.RED;if(i===oh)return n.RED_INTEGER;if(i===lr)return n.RG;if(i===ah)return n.RG_INTEGER;if(i===lh)return n.RGBA_INTEGER;if(i===$a||i===qa||i===Ya||i===Za)if(o===Ft)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(i===$a)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===qa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===Ya)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===Za)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(i===$a)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===qa)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===Ya)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===Za)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===ch||i===hh||i===uh||i===fh)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(i===ch)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===hh)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===uh)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===fh)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===dh||i===ph||i===mh||i===gh||i===_h||i===Ka||i===yh)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(i===dh||i===ph)return o===Ft?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(i===mh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(i===gh)return r.COMPRESSED_R11_EAC;if(i===_h)return r.COMPRESSED_SIGNED_R11_EAC;if(i===Ka)return r.COMPRESSED_RG11_EAC;if(i===yh)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===xh||i===vh||i===bh||i===Sh||i===Mh||i===wh||i===Eh||i===Th||i===Ah||i===Rh||i===Ch||i===Ih||i===Ph||i===Lh)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(i===xh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===vh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===bh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===Sh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===Mh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===wh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===Eh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===Th)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===Ah)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===Rh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===Ch)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===Ih)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===Ph)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===Lh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===Nh||i===Dh||i===Uh)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(i===Nh)return o===Ft?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===Dh)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===Uh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Oh||i===Fh||i===Ja||i===Bh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(i===Oh)return r.COMPRESSED_RED_RGTC1_EXT;if(i===Fh)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===Ja)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===Bh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Dr?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:t}}var YE=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,ZE=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,Ad=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){let i=new Fa(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,i=new ns({vertexShader:YE,fragmentShader:ZE,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new ts(new Ba(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Rd=class extends Fi{constructor(e,t){super();let i=this,s=null,r=1,o=null,a="local-floor",l=1,c=null,h=null,f=null,u=null,m=null,g=null,v=typeof XRWebGLBinding<"u",d=new Ad,p={},x=t.getContextAttributes(),A=null,S=null,C=[],T=[],_=new pt,w=null,U=null,N=new Yn;N.viewport=new rn;let R=new Yn;R.viewport=new rn;let G=[N,R],B=new jc,L=null,z=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(Q){let me=C[Q];return me===void 0&&(me=new Co,C[Q]=me),me.getTargetRaySpace()},this.getControllerGrip=function(Q){let me=C[Q];return me===void 0&&(me=new Co,C[Q]=me),me.getGripSpace()},this.getHand=function(Q){let me=C[Q];return me===void 0&&(me=new Co,C[Q]=me),me.getHandSpace()};function q(Q){let me=T.indexOf(Q.inputSource);if(me===-1)return;let pe=C[me];pe!==void 0&&(pe.update(Q.inputSource,Q.frame,c||o),pe.dispatchEvent({type:Q.type,data:Q.inputSource}))}function O(){s.removeEventListener("select",q),s.removeEventListener("selectstart",q),s.removeEventListener("selectend",q),s.removeEventListener("squeeze",q),s.removeEventListener("squeezestart",q),s.removeEventListener("squeezeend",q),s.removeEventListener("end",O),s.removeEventListener("inputsourceschange",re);for(let Q=0;Q<C.length;Q++){let me=T[Q];me!==null&&(T[Q]=null,C[Q].disconnect(me))}L=null,z=null,d.reset();for(let Q in p)delete p[Q];if(e.setRenderTarget(A),m=null,u=null,f=null,s=null,S=null,le.stop(),i.isPresenting=!1,e.setPixelRatio(w),e.setSize(_.width,_.height,!1),U!==null){let Q=U.camera;Q.fov=U.fov,Q.zoom=U.zoom,Q.updateProjectionMatrix(),U=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(Q){r=Q,i.isPresenting===!0&&je("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(Q){a=Q,i.isPresenting===!0&&je("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||o},this.setReferenceSpace=function(Q){c=Q},this.getBaseLayer=function(){return u!==null?u:m},this.getBinding=function(){return f===null&&v&&(f=new XRWebGLBinding(s,t)),f},this.getFrame=function(){return g},this.getSession=function(){return s},this.setSession=async function(Q){if(s=Q,s!==null){if(A=e.getRenderTarget(),s.addEventListener("select",q),s.addEventListener("selectstart",q),s.addEventListener("selectend",q),s.addEventListener("squeeze",q),s.addEventListener("squeezestart",q),s.addEventListener("squeezeend",q),s.addEventListener("end",O),s.addEventListener("inputsourceschange",re),x.xrCompatible!==!0&&await t.makeXRCompatible(),w=e.getPixelRatio(),e.getSize(_),v&&"createProjectionLayer"in XRWebGLBinding.prototype){let pe=null,be=null,xe=null;x.depth&&(xe=x.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,pe=x.stencil?As:Ms,be=x.stencil?Dr:Bi);let We={colorFormat:t.RGBA8,depthFormat:xe,scaleFactor:r};f=this.getBinding(),u=f.createProjectionLayer(We),s.updateRenderState({layers:[u]}),e.setPixelRatio(1),e.setSize(u.textureWidth,u.textureHeight,!1),S=new _i(u.textureWidth,u.textureHeight,{format:Gi,type:xi,depthTexture:new Es(u.textureWidth,u.textureHeight,be,void 0,void 0,void 0,void 0,void 0,void 0,pe),stencilBuffer:x.stencil,colorSpace:e.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:u.ignoreDepthValues===!1,resolveStencilBuffer:u.ignoreDepthValues===!1,storeMultisampledDepthBuffer:u.ignoreDepthValues===!1,storeMultisampledStencilBuffer:u.ignoreDepthValues===!1})}else{let pe={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,pe),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),S=new _i(m.framebufferWidth,m.framebufferHeight,{format:Gi,type:xi,colorSpace:e.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}S.isXRRenderTarget=!0,this.setFoveation(l),c=null,o=await s.requestReferenceSpace(a),le.setContext(s),le.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return d.getDepthTexture()};function re(Q){for(let me=0;me<Q.removed.length;me++){let pe=Q.removed[me],be=T.indexOf(pe);be>=0&&(T[be]=null,C[be].disconnect(pe))}for(let me=0;me<Q.added.length;me++){let pe=Q.added[me],be=T.indexOf(pe);if(be===-1){for(let We=0;We<C.length;We++)if(We>=T.length){T.push(pe),be=We;break}else if(T[We]===null){T[We]=pe,be=We;break}if(be===-1)break}let xe=C[be];xe&&xe.connect(pe)}}function X(Q,me){me===null?Q.matrixWorld.copy(Q.matrix):Q.matrixWorld.multiplyMatrices(me.matrixWorld,Q.matrix),Q.matrixWorldInverse.copy(Q.matrixWorld).invert()}this.updateCamera=function(Q){if(s===null)return;let me=Q.near,pe=Q.far;d.texture!==null&&(d.depthNear>0&&(me=d.depthNear),d.depthFar>0&&(pe=d.depthFar)),B.near=R.near=N.near=me,B.far=R.far=N.far=pe,(L!==B.near||z!==B.far)&&(s.updateRenderState({depthNear:B.near,depthFar:B.far}),L=B.near,z=B.far),B.layers.mask=Q.layers.mask|6,N.layers.mask=B.layers.mask&-5,R.layers.mask=B.layers.mask&-3;let be=Q.parent,xe=B.cameras;X(B,be);for(let We=0;We<xe.length;We++)X(xe[We],be);B.projectionMatrix.copy(N.projectionMatrix),B.projectionMatrixInverse.copy(N.projectionMatrixInverse),U===null&&Q.isPerspectiveCamera&&(U={camera:Q,fov:Q.fov,zoom:Q.zoom}),$(Q,B,be)};function $(Q,me,pe){pe===null?Q.matrix.copy(me.matrixWorld):(Q.matrix.copy(pe.matrixWorld),Q.matrix.invert(),Q.matrix.multiply(me.matrixWorld)),Q.matrix.decompose(Q.position,Q.quaternion,Q.scale),Q.updateMatrixWorld(!0),Q.projectionMatrix.copy(me.projectionMatrix),Q.projectionMatrixInverse.copy(me.projectionMatrixInverse),Q.isPerspectiveCamera&&(Q.fov=Ao*2*Math.atan(1/Q.projectionMatrix.elements[5]),Q.zoom=1)}this.getCamera=function(){return B},this.getFoveation=function(){if(!(u===null&&m===null))return l},this.setFoveation=function(Q){l=Q,u!==null&&(u.fixedFoveation=Q),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=Q)},this.hasDepthSensing=function(){return d.texture!==null},this.getDepthSensingMesh=function(){return d.getMesh(B)},this.getCameraTexture=function(Q){return p[Q]};let W=null;function ne(Q,me){if(h=me.getViewerPose(c||o),g=me,h!==null){let pe=h.views;m!==null&&(e.setRenderTargetFramebuffer(S,m.framebuffer),e.setRenderTarget(S));let be=!1;pe.length!==B.cameras.length&&(B.cameras.length=0,be=!0);for(let Ne=0;Ne<pe.length;Ne++){let qe=pe[Ne],tt=null;if(m!==null)tt=m.getViewport(qe);else{let ke=f.getViewSubImage(u,qe);tt=ke.viewport,Ne===0&&(e.setRenderTargetTextures(S,ke.colorTexture,ke.depthStencilTexture),e.setRenderTarget(S))}let fe=G[Ne];fe===void 0&&(fe=new Yn,fe.layers.enable(Ne),fe.viewport=new rn,G[Ne]=fe),fe.matrix.fromArray(qe.transform.matrix),fe.matrix.decompose(fe.position,fe.quaternion,fe.scale),fe.projectionMatrix.fromArray(qe.projectionMatrix),fe.projectionMatrixInverse.copy(fe.projectionMatrix).invert(),fe.viewport.set(tt.x,tt.y,tt.width,tt.height),Ne===0&&(B.matrix.copy(fe.matrix),B.matrix.decompose(B.position,B.quaternion,B.scale)),be===!0&&B.cameras.push(fe)}let xe=s.enabledFeatures;if(xe&&xe.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&v){f=i.getBinding();let Ne=f.getDepthInformation(pe[0]);Ne&&Ne.isValid&&Ne.texture&&d.init(Ne,s.renderState)}if(xe&&xe.includes("camera-access")&&v){e.state.unbindTexture(),f=i.getBinding();for(let Ne=0;Ne<pe.length;Ne++){let qe=pe[Ne].camera;if(qe){let tt=p[qe];tt||(tt=new Fa,p[qe]=tt);let fe=f.getCameraImage(qe);tt.sourceTexture=fe}}}}for(let pe=0;pe<C.length;pe++){let be=T[pe],xe=C[pe];be!==null&&xe!==void 0&&xe.update(be,me,c||o)}W&&W(Q,me),me.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:me}),g=null}let le=new l_;le.setAnimationLoop(ne),this.setAnimationLoop=function(Q){W=Q},this.dispose=function(){}}},KE=new tn,y_=new lt;y_.set(-1,0,0,0,1,0,0,0,1);function JE(n,e){function t(d,p){d.matrixAutoUpdate===!0&&d.updateMatrix(),p.value.copy(d.matrix)}function i(d,p){p.color.getRGB(d.fogColor.value,hd(n)),p.isFog?(d.fogNear.value=p.near,d.fogFar.value=p.far):p.isFogExp2&&(d.fogDensity.value=p.density)}function s(d,p,x,A,S){p.isNodeMaterial?p.uniformsNeedUpdate=!1:p.isMeshBasicMaterial?r(d,p):p.isMeshLambertMaterial?(r(d,p),p.envMap&&(d.envMapIntensity.value=p.envMapIntensity)):p.isMeshToonMaterial?(r(d,p),f(d,p)):p.isMeshPhongMaterial?(r(d,p),h(d,p),p.envMap&&(d.envMapIntensity.value=p.envMapIntensity)):p.isMeshStandardMaterial?(r(d,p),u(d,p),p.isMeshPhysicalMaterial&&m(d,p,S)):p.isMeshMatcapMaterial?(r(d,p),g(d,p)):p.isMeshDepthMaterial?r(d,p):p.isMeshDistanceMaterial?(r(d,p),v(d,p)):p.isMeshNormalMaterial?r(d,p):p.isLineBasicMaterial?(o(d,p),p.isLineDashedMaterial&&a(d,p)):p.isPointsMaterial?l(d,p,x,A):p.isSpriteMaterial?c(d,p):p.isShadowMaterial?(d.color.value.copy(p.color),d.opacity.value=p.opacity):p.isShaderMaterial&&(p.uniformsNeedUpdate=!1)}function r(d,p){d.opacity.value=p.opacity,p.color&&d.diffuse.value.copy(p.color),p.emissive&&d.emissive.value.copy(p.emissive).multiplyScalar(p.emissiveIntensity),p.map&&(d.map.value=p.map,t(p.map,d.mapTransform)),p.alphaMap&&(d.alphaMap.value=p.alphaMap,t(p.alphaMap,d.alphaMapTransform)),p.bumpMap&&(d.bumpMap.value=p.bumpMap,t(p.bumpMap,d.bumpMapTransform),d.bumpScale.value=p.bumpScale,p.side===Kn&&(d.bumpScale.value*=-1)),p.normalMap&&(d.normalMap.value=p.normalMap,t(p.normalMap,d.normalMapTransform),d.normalScale.value.copy(p.normalScale),p.side===Kn&&d.normalScale.value.negate()),p.displacementMap&&(d.displacementMap.value=p.displacementMap,t(p.displacementMap,d.displacementMapTransform),d.displacementScale.value=p.displacementScale,d.displacementBias.value=p.displacementBias),p.emissiveMap&&(d.emissiveMap.value=p.emissiveMap,t(p.emissiveMap,d.emissiveMapTransform)),p.specularMap&&(d.specularMap.value=p.specularMap,t(p.specularMap,d.specularMapTransform)),p.alphaTest>0&&(d.alphaTest.value=p.alphaTest);let x=e.get(p),A=x.envMap,S=x.envMapRotation;A&&(d.envMap.value=A,d.envMapRotation.value.setFromMatrix4(KE.makeRotationFromEuler(S)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&d.envMapRotation.value.premultiply(y_),d.reflectivity.value=p.reflectivity,d.ior.value=p.ior,d.refractionRatio.value=p.refractionRatio),p.lightMap&&(d.lightMap.value=p.lightMap,d.lightMapIntensity.value=p.lightMapIntensity,t(p.lightMap,d.lightMapTransform)),p.aoMap&&(d.aoMap.value=p.aoMap,d.aoMapIntensity.value=p.aoMapIntensity,t(p.aoMap,d.aoMapTransform))}function o(d,p){d.diffuse.value.copy(p.color),d.opacity.value=p.opacity,p.map&&(d.map.value=p.map,t(p.map,d.mapTransform))}function a(d,p){d.dashSize.value=p.dashSize,d.totalSize.value=p.dashSize+p.gapSize,d.scale.value=p.scale}function l(d,p,x,A){d.diffuse.value.copy(p.color),d.opacity.value=p.opacity,d.size.value=p.size*x,d.scale.value=A*.5,p.map&&(d.map.value=p.map,t(p.map,d.uvTransform)),p.alphaMap&&(d.alphaMap.value=p.alphaMap,t(p.alphaMap,d.alphaMapTransform)),p.alphaTest>0&&(d.alphaTest.value=p.alphaTest)}function c(d,p){d.diffuse.value.copy(p.color),d.opacity.value=p.opacity,d.rotation.value=p.rotation,p.map&&(d.map.value=p.map,t(p.map,d.mapTransform)),p.alphaMap&&(d.alphaMap.value=p.alphaMap,t(p.alphaMap,d.alphaMapTransform)),p.alphaTest>0&&(d.alphaTest.value=p.alphaTest)}function h(d,p){d.specular.value.copy(p.specular),d.shininess.value=Math.max(p.shininess,1e-4)}function f(d,p){p.gradientMap&&(d.gradientMap.value=p.gradientMap)}function u(d,p){d.metalness.value=p.metalness,p.metalnessMap&&(d.metalnessMap.value=p.metalnessMap,t(p.metalnessMap,d.metalnessMapTransform)),d.roughness.value=p.roughness,p.roughnessMap&&(d.roughnessMap.value=p.roughnessMap,t(p.roughnessMap,d.roughnessMapTransform)),p.envMap&&(d.envMapIntensity.value=p.envMapIntensity)}function m(d,p,x){d.ior.value=p.ior,p.diffuseRoughness>0&&(d.diffuseRoughness.value=p.diffuseRoughness,p.diffuseRoughnessMap&&(d.diffuseRoughnessMap.value=p.diffuseRoughnessMap,t(p.diffuseRoughnessMap,d.diffuseRoughnessMapTransform))),p.sheen>0&&(d.sheenColor.value.copy(p.sheenColor).multiplyScalar(p.sheen),d.sheenRoughness.value=p.sheenRoughness,p.sheenColorMap&&(d.sheenColorMap.value=p.sheenColorMap,t(p.sheenColorMap,d.sheenColorMapTransform)),p.sheenRoughnessMap&&(d.sheenRoughnessMap.value=p.sheenRoughnessMap,t(p.sheenRoughnessMap,d.sheenRoughnessMapTransform))),p.clearcoat>0&&(d.clearcoat.value=p.clearcoat,d.clearcoatRoughness.value=p.clearcoatRoughness,p.clearcoatMap&&(d.clearcoatMap.value=p.clearcoatMap,t(p.clearcoatMap,d.clearcoatMapTransform)),p.clearcoatRoughnessMap&&(d.clearcoatRoughnessMap.value=p.clearcoatRoughnessMap,t(p.clearcoatRoughnessMap,d.clearcoatRoughnessMapTransform)),p.clearcoatNormalMap&&(d.clearcoatNormalMap.value=p.clearcoatNormalMap,t(p.clearcoatNormalMap,d.clearcoatNormalMapTransform),d.clearcoatNormalScale.value.copy(p.clearcoatNormalScale),p.side===Kn&&d.clearcoatNormalScale.value.negate())),p.dispersion>0&&(d.dispersion.value=p.dispersion),p.retroreflectivity>0&&(d.retroreflectivity.value=p.retroreflectivity),p.iridescence>0&&(d.iridescence.value=p.iridescence,d.iridescenceIOR.value=p.iridescenceIOR,d.iridescenceThicknessMinimum.value=p.iridescenceThicknessMinimum,d.iridescenceThicknessMaximum.value=p.iridescenceThicknessMaximum,p.iridescenceMap&&(d.iridescenceMap.value=p.iridescenceMap,t(p.iridescenceMap,d.iridescenceMapTransform)),p.iridescenceThicknessMap&&(d.iridescenceThicknessMap.value=p.iridescenceThicknessMap,t(p.iridescenceThicknessMap,d.iridescenceThicknessMapTransform))),p.transmission>0&&(d.transmission.value=p.transmission,d.transmissionSamplerMap.value=x.texture,d.transmissionSamplerSize.value.set(x.width,x.height),p.transmissionMap&&(d.transmissionMap.value=p.transmissionMap,t(p.transmissionMap,d.transmissionMapTransform)),d.thickness.value=p.thickness,p.thicknessMap&&(d.thicknessMap.value=p.thicknessMap,t(p.thicknessMap,d.thicknessMapTransform)),d.attenuationDistance.value=p.attenuationDistance,d.attenuationColor.value.copy(p.attenuationColor)),p.anisotropy>0&&(d.anisotropyVector.value.set(p.anisotropy*Math.cos(p.anisotropyRotation),p.anisotropy*Math.sin(p.anisotropyRotation)),p.anisotropyMap&&(d.anisotropyMap.value=p.anisotropyMap,t(p.anisotropyMap,d.anisotropyMapTransform))),d.specularIntensity.value=p.specularIntensity,d.specularColor.value.copy(p.specularColor),p.specularColorMap&&(d.specularColorMap.value=p.specularColorMap,t(p.specularColorMap,d.specularColorMapTransform)),p.specularIntensityMap&&(d.specularIntensityMap.value=p.specularIntensityMap,t(p.specularIntensityMap,d.specularIntensityMapTransform))}function g(d,p){p.matcap&&(d.matcap.value=p.matcap)}function v(d,p){let x=e.get(p).light;d.referencePosition.value.setFromMatrixPosition(x.matrixWorld),d.nearDistance.value=x.shadow.camera.near,d.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:s}}function jE(n,e,t,i){let s={},r={};function o(x,A){let S=A.program;i.uniformBlockBinding(x,S,s[x.id])}function a(x,A){let S=s[x.id];S===void 0&&(g(x),S=l(x),s[x.id]=S,x.addEventListener("dispose",d));let C=A.program;i.updateUBOMapping(x,C);let T=e.render.frame;r[x.id]!==T&&(c(x),r[x.id]=T)}function l(x){let A=n.createBuffer(),S=x.__size,C=x.usage;return n.bindBuffer(n.UNIFORM_BUFFER,A),n.bufferData(n.UNIFORM_BUFFER,S,C),n.bindBuffer(n.UNIFORM_BUFFER,null),A}function c(x){let A=s[x.id],S=x.uniforms,C=x.__cache;n.bindBuffer(n.UNIFORM_BUFFER,A);for(let T=0,_=S.length;T<_;T++){let w=S[T];if(Array.isArray(w))for(let U=0,N=w.length;U<N;U++)h(w[U],T,U,C);else h(w,T,0,C)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function h(x,A,S,C){if(u(x,A,S,C)===!0){let T=x.__offset,_=x.value;if(Array.isArray(_)){let w=0;for(let U=0;U<_.length;U++){let N=_[U],R=v(N,!0);f(N,x.__data,w),w+=R.storage/Float32Array.BYTES_PER_ELEMENT}}else f(_,x.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,T,x.__data)}}function f(x,A,S){typeof x=="number"||typeof x=="boolean"?A[S]=x:x.isMatrix3?(A[S]=x.elements[0],A[S+1]=x.elements[1],A[S+2]=x.elements[2],A[S+3]=0,A[S+4]=x.elements[3],A[S+5]=x.elements[4],A[S+6]=x.elements[5],A[S+7]=0,A[S+8]=x.elements[6],A[S+9]=x.elements[7],A[S+10]=x.elements[8],A[S+11]=0):ArrayBuffer.isView(x)?A.set(x.subarray(0,A.length-S),S):x.toArray(A,S)}function u(x,A,S,C){let T=x.value,_=A+"_"+S;if(Array.isArray(T)){C[_]===void 0&&(C[_]=[]);let w=C[_],U=!1;for(let N=0;N<T.length;N++)m(T[N],w,N)===!0&&(U=!0);return U}return m(T,C,_)}function m(x,A,S){if(A[S]===void 0)return typeof x=="number"||typeof x=="boolean"?A[S]=x:ArrayBuffer.isView(x)?A[S]=x.slice():A[S]=x.clone(),!0;{let C=A[S];if(typeof x=="number"||typeof x=="boolean"){if(C!==x)return A[S]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(C.equals(x)===!1)return C.copy(x),!0}}return!1}function g(x){let A=x.uniforms,S=0,C=16;for(let _=0,w=A.length;_<w;_++){let U=Array.isArray(A[_])?A[_]:[A[_]];for(let N=0,R=U.length;N<R;N++){let G=U[N],B=Array.isArray(G.value)?G.value:[G.value],L=Array.isArray(A[_])||Array.isArray(G.value),z=S;for(let O=0,re=B.length;O<re;O++){let X=B[O],$=v(X,L),W=S%C,ne=W%$.boundary,le=W+ne;S+=ne,le!==0&&C-le<$.storage&&(S+=C-le),O===0&&(z=S),S+=$.storage}let q=G.type==="int"?Int32Array:G.type==="uint"?Uint32Array:Float32Array;G.__data=new q((S-z)/Float32Array.BYTES_PER_ELEMENT),G.__offset=z}}let T=S%C;return T>0&&(S+=C-T),x.__size=S,x.__cache={},this}function v(x,A){let S={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(S.boundary=4,S.storage=4):x.isVector2?(S.boundary=8,S.storage=8):x.isVector3||x.isColor?(S.boundary=16,S.storage=12):x.isVector4?(S.boundary=16,S.storage=16):x.isMatrix3?(S.boundary=16,S.storage=48):x.isMatrix4?(S.boundary=16,S.storage=64):x.isTexture?je("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(S.boundary=16,S.storage=x.byteLength):je("WebGLRenderer: Unsupported uniform value type.",x),A===!0&&(S.boundary=16,S.storage=Math.ceil(S.storage/16)*16),S}function d(x){let A=x.target;A.removeEventListener("dispose",d),n.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function p(){for(let x in s)n.deleteBuffer(s[x]);s={},r={}}return{bind:o,update:a,dispose:p}}var QE=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),rs=null;function eT(){return rs===null&&(rs=new Nc(QE,16,16,lr,zi),rs.name="DFG_LUT",rs.minFilter=Zn,rs.magFilter=Zn,rs.wrapS=es,rs.wrapT=es,rs.generateMipmaps=!1,rs.needsUpdate=!0),rs}var Hh=class{constructor(e={}){let{canvas:t=P0(),context:i=null,depth:s=!0,stencil:r=!1,alpha:o=!1,antialias:a=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:f=!1,reversedDepthBuffer:u=!1,outputBufferType:m=xi}=e;this.isWebGLRenderer=!0;let g;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");g=i.getContextAttributes().alpha}else g=o;let v=m,d=new Set([lh,ah,oh]),p=new Set([xi,Bi,Bo,Dr,sh,rh]),x=new Uint32Array(4),A=new Int32Array(4),S={textures:[],min:[],max:[],resolution:[]},C=null,T=null,_=[],w=[],U=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ss,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let N=this,R=!1,G=null,B=null,L=null,z=null;this._outputColorSpace=di;let q=0,O=0,re=null,X=-1,$=null,W=new rn,ne=new rn,le=null,Q=new _t(0),me=0,pe=t.width,be=t.height,xe=1,We=null,Qe=null,Ne=new rn(0,0,pe,be),qe=new rn(0,0,pe,be),tt=!1,fe=new Ir,ke=new Dc,Ze=!1,Rt=!1,wt=new tn,Vt=new J,et=new rn,Ct={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},ut=!1;function ft(){return re===null?xe:1}let F=i;function ge(E,H){return t.getContext(E,H)}let Ke,dt,Ae,Wt,Xe,Je,I,b,Y,de,ce,Me,we,ie,oe,ye,k,ae,se,Re,Se,Te,$e;try{let E={alpha:!0,depth:s,stencil:r,antialias:a,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:f};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${"187"}`),t.addEventListener("webglcontextlost",Ge,!1),t.addEventListener("webglcontextrestored",rt,!1),t.addEventListener("webglcontextcreationerror",Pe,!1),F===null){let H="webgl2";if(F=ge(H,E),F===null)throw ge(H)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}st()}catch(E){throw t.removeEventListener("webglcontextlost",Ge,!1),t.removeEventListener("webglcontextrestored",rt,!1),t.removeEventListener("webglcontextcreationerror",Pe,!1),at("WebGLRenderer: "+E.message),E}function st(){Ke=new uw(F),Ke.init(),Se=new qE(F,Ke),dt=new ew(F,Ke,e,Se),Ae=new XE(F,Ke),dt.reversedDepthBuffer&&u&&Ae.buffers.depth.setReversed(!0),B=F.createFramebuffer(),L=F.createFramebuffer(),z=F.createFramebuffer(),Wt=new pw(F),Xe=new PE,Je=new $E(F,Ke,Ae,Xe,dt,Se,Wt),I=new hw(N),b=new gb(F),Te=new jM(F,b),Y=new fw(F,b,Wt,Te),de=new gw(F,Y,b,Te,Wt),ae=new mw(F,dt,Je),oe=new tw(Xe),ce=new IE(N,I,Ke,dt,Te,oe),Me=new JE(N,Xe),we=new NE,ie=new kE(Ke),k=new JM(N,I,Ae,de,g,l),ye=new WE(N,de,dt),$e=new jE(F,Wt,dt,Ae),se=new QM(F,Ke,Wt),Re=new dw(F,Ke,Wt),Wt.programs=ce.programs,N.capabilities=dt,N.extensions=Ke,N.properties=Xe,N.renderLists=we,N.shadowMap=ye,N.state=Ae,N.info=Wt}v!==xi&&(U=new yw(v,t.width,t.height,a,s,r));let ue=new Rd(N,F);this.xr=ue,this.getContext=function(){return F},this.getContextAttributes=function(){return F.getContextAttributes()},this.forceContextLoss=function(){let E=Ke.get("WEBGL_lose_context");E&&E.loseContext()},this.forceContextRestore=function(){let E=Ke.get("WEBGL_lose_context");E&&E.restoreContext()},this.getPixelRatio=function(){return xe},this.setPixelRatio=function(E){E!==void 0&&(xe=E,this.setSize(pe,be,!1))},this.getSize=function(E){return E.set(pe,be)},this.setSize=function(E,H,ee=!0){if(ue.isPresenting){je("WebGLRenderer: Can't change size while VR device is presenting.");return}pe=E,be=H,t.width=Math.floor(E*xe),t.height=Math.floor(H*xe),ee===!0&&(t.style.width=E+"px",t.style.height=H+"px"),U!==null&&U.setSize(t.width,t.height),this.setViewport(0,0,E,H)},this.getDrawingBufferSize=function(E){return E.set(pe*xe,be*xe).floor()},this.setDrawingBufferSize=function(E,H,ee){pe=E,be=H,xe=ee,t.width=Math.floor(E*ee),t.height=Math.floor(H*ee),this.setViewport(0,0,E,H)},this.setEffects=function(E){if(v===xi){at("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(E){for(let H=0;H<E.length;H++)if(E[H].isOutputPass===!0){je("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}U.setEffects(E||[])},this.getCurrentViewport=function(E){return E.copy(W)},this.getViewport=function(E){return E.copy(Ne)},this.setViewport=function(E,H,ee,Z){E.isVector4?Ne.set(E.x,E.y,E.z,E.w):Ne.set(E,H,ee,Z),Ae.viewport(W.copy(Ne).multiplyScalar(ft()).round())},this.getScissor=function(E){return E.copy(qe)},this.setScissor=function(E,H,ee,Z){E.isVector4?qe.set(E.x,E.y,E.z,E.w):qe.set(E,H,ee,Z),Ae.scissor(ne.copy(qe).multiplyScalar(ft()).round())},this.getScissorTest=function(){return tt},this.setScissorTest=function(E){Ae.setScissorTest(tt=E)},this.setOpaqueSort=function(E){We=E},this.setTransparentSort=function(E){Qe=E},this.getClearColor=function(E){return E.copy(k.getClearColor())},this.setClearColor=function(){k.setClearColor(...arguments)},this.getClearAlpha=function(){return k.getClearAlpha()},this.setClearAlpha=function(){k.setClearAlpha(...arguments)},this.clear=function(E=!0,H=!0,ee=!0){let Z=0;if(E){let K=!1;if(re!==null){let Ce=re.texture.format;K=d.has(Ce)}if(K){let Ce=re.texture.type,Le=p.has(Ce),Ie=k.getClearColor(),De=k.getClearAlpha(),Ve=Ie.r,ot=Ie.g,xt=Ie.b;Le?(x[0]=Ve,x[1]=ot,x[2]=xt,x[3]=De,F.clearBufferuiv(F.COLOR,0,x)):(A[0]=Ve,A[1]=ot,A[2]=xt,A[3]=De,F.clearBufferiv(F.COLOR,0,A))}else Z|=F.COLOR_BUFFER_BIT}H&&(Z|=F.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),ee&&(Z|=F.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),Z!==0&&F.clear(Z)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(E){E.setRenderer(this),G=E},this.dispose=function(){t.removeEventListener("webglcontextlost",Ge,!1),t.removeEventListener("webglcontextrestored",rt,!1),t.removeEventListener("webglcontextcreationerror",Pe,!1),k.dispose(),we.dispose(),ie.dispose(),Je.dispose(),Xe.dispose(),I.dispose(),de.dispose(),Y.dispose(),Te.dispose(),$e.dispose(),ce.dispose(),ue.dispose(),ue.removeEventListener("sessionstart",sl),ue.removeEventListener("sessionend",Vi),as.stop()};function Ge(E){E.preventDefault(),rd("WebGLRenderer: Context Lost."),R=!0}function rt(){rd("WebGLRenderer: Context Restored."),R=!1;let E=Wt.autoReset,H=ye.enabled,ee=ye.autoUpdate,Z=ye.needsUpdate,K=ye.type;st(),Wt.autoReset=E,ye.enabled=H,ye.autoUpdate=ee,ye.needsUpdate=Z,ye.type=K}function Pe(E){at("WebGLRenderer: A WebGL context could not be created. Reason: ",E.statusMessage)}function mt(E){let H=E.target;H.removeEventListener("dispose",mt),qt(H)}function qt(E){Hn(E),Xe.remove(E)}function Hn(E){let H=Xe.get(E).programs;H!==void 0&&(H.forEach(function(ee){ce.releaseProgram(ee)}),E.isShaderMaterial&&ce.releaseShaderCache(E))}this.renderBufferDirect=function(E,H,ee,Z,K,Ce){H===null&&(H=Ct);let Le=K.isMesh&&K.matrixWorld.determinantAffine()<0,Ie=Xo(E,H,ee,Z,K);Ae.setMaterial(Z,Le);let De=ee.index,Ve=1;if(Z.wireframe===!0){if(De=Y.getWireframeAttribute(ee),De===void 0)return;Ve=2}let ot=ee.drawRange,xt=ee.attributes.position,He=ot.start*Ve,vt=(ot.start+ot.count)*Ve;Ce!==null&&(He=Math.max(He,Ce.start*Ve),vt=Math.min(vt,(Ce.start+Ce.count)*Ve)),De!==null?(He=Math.max(He,0),vt=Math.min(vt,De.count)):xt!=null&&(He=Math.max(He,0),vt=Math.min(vt,xt.count));let nn=vt-He;if(nn<0||nn===1/0)return;Te.setup(K,Z,Ie,ee,De);let Bt,kt=se;if(De!==null&&(Bt=b.get(De),kt=Re,kt.setIndex(Bt)),K.isMesh)Z.wireframe===!0?(Ae.setLineWidth(Z.wireframeLinewidth*ft()),kt.setMode(F.LINES)):kt.setMode(F.TRIANGLES);else if(K.isLine){let vn=Z.linewidth;vn===void 0&&(vn=1),Ae.setLineWidth(vn*ft()),K.isLineSegments?kt.setMode(F.LINES):K.isLineLoop?kt.setMode(F.LINE_LOOP):kt.setMode(F.LINE_STRIP)}else K.isPoints?kt.setMode(F.POINTS):K.isSprite&&kt.setMode(F.TRIANGLES);if(K.isBatchedMesh)if(Ke.get("WEBGL_multi_draw"))kt.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{let vn=K._multiDrawStarts,Be=K._multiDrawCounts,fn=K._multiDrawCount,Et=De?b.get(De).bytesPerElement:1,cs=Xe.get(Z).currentProgram.getUniforms();for(let dn=0;dn<fn;dn++)cs.setValue(F,"_gl_DrawID",dn),kt.render(vn[dn]/Et,Be[dn])}else if(K.isInstancedMesh)kt.renderInstances(He,nn,K.count);else if(ee.isInstancedBufferGeometry){let vn=ee._maxInstanceCount!==void 0?ee._maxInstanceCount:1/0,Be=Math.min(ee.instanceCount,vn);kt.renderInstances(He,nn,Be)}else kt.render(He,nn)};function Ho(E,H,ee,Z){G!==null&&E.isNodeMaterial&&G.setObject(Z,E),Ze===!0&&oe.setState(E,ee,!1),E.transparent===!0&&E.side===is&&E.forceSinglePass===!1?(E.side=Kn,E.needsUpdate=!0,Wi(E,H,Z),E.side=ar,E.needsUpdate=!0,Wi(E,H,Z),E.side=is):Wi(E,H,Z)}this.compile=function(E,H,ee=null){ee===null&&(ee=E),G!==null&&G.renderStart(E,H,ee),T=ie.get(ee),T.init(H),w.push(T),ee.traverseVisible(function(K){K.isLight&&K.layers.test(H.layers)&&(T.pushLight(K),K.castShadow&&T.pushShadow(K))}),E!==ee&&E.traverseVisible(function(K){K.isLight&&K.layers.test(H.layers)&&(T.pushLight(K),K.castShadow&&T.pushShadow(K))}),T.setupLights(),G!==null&&G.updateLights(T.state.lightsArray),Rt=this.localClippingEnabled,Ze=oe.init(this.clippingPlanes,Rt),Ze===!0&&oe.setGlobalState(this.clippingPlanes,H),G!==null&&ye.render(T.state.shadowsArray,ee,H);let Z=new Set;return E.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;let Ce=K.material;if(Ce)if(Array.isArray(Ce))for(let Le=0;Le<Ce.length;Le++){let Ie=Ce[Le];Ho(Ie,ee,H,K),Z.add(Ie)}else Ho(Ce,ee,H,K),Z.add(Ce)}),T=w.pop(),G!==null&&G.renderEnd(),Z},this.compileAsync=function(E,H,ee=null){let Z=this.compile(E,H,ee);return new Promise(K=>{function Ce(){if(Z.forEach(function(Le){let De=Xe.get(Le).currentProgram;(De===void 0||De.isReady())&&Z.delete(Le)}),Z.size===0){K(E);return}setTimeout(Ce,10)}Ke.get("KHR_parallel_shader_compile")!==null?Ce():setTimeout(Ce,10)})};let Fr=null;function Kh(E){Fr&&Fr(E)}function sl(){as.stop()}function Vi(){as.start()}let as=new l_;as.setAnimationLoop(Kh),typeof self<"u"&&as.setContext(self),this.setAnimationLoop=function(E){Fr=E,ue.setAnimationLoop(E),E===null?as.stop():as.start()},ue.addEventListener("sessionstart",sl),ue.addEventListener("sessionend",Vi),this.render=function(E,H){if(H!==void 0&&H.isCamera!==!0){at("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(R===!0)return;G!==null&&G.renderStart(E,H);let ee=ue.enabled===!0&&ue.isPresenting===!0,Z=U!==null&&(re===null||ee)&&U.begin(N,re);if(E.matrixWorldAutoUpdate===!0&&E.updateMatrixWorld(),H.parent===null&&H.matrixWorldAutoUpdate===!0&&H.updateMatrixWorld(),ue.enabled===!0&&ue.isPresenting===!0&&(U===null||U.isCompositing()===!1)&&(ue.cameraAutoUpdate===!0&&ue.updateCamera(H),H=ue.getCamera()),E.isScene===!0&&E.onBeforeRender(N,E,H,re),T=ie.get(E,w.length),T.init(H),T.state.textureUnits=Je.getTextureUnits(),w.push(T),wt.multiplyMatrices(H.projectionMatrix,H.matrixWorldInverse),H.isArrayCamera?ke.setFromArrayCamera(H):fe.setFromProjectionMatrix(wt,Ti,H.reversedDepth),Rt=this.localClippingEnabled,Ze=oe.init(this.clippingPlanes,Rt),C=we.get(E,_.length),C.init(),_.push(C),this.info.render.frame++,ue.enabled===!0&&ue.isPresenting===!0){let Le=N.xr.getDepthSensingMesh();Le!==null&&ls(Le,H,-1/0,N.sortObjects)}ls(E,H,0,N.sortObjects),C.finish(),G!==null&&G.updateLights(T.state.lightsArray),N.sortObjects===!0&&C.sort(We,Qe),ut=ue.enabled===!1||ue.isPresenting===!1||ue.hasDepthSensing()===!1,ut&&k.addToRenderList(C,E),this.info.autoReset===!0&&this.info.reset(),Ze===!0&&oe.beginShadows();let K=T.state.shadowsArray;if(ye.render(K,E,H),Ze===!0&&oe.endShadows(),(Z&&U.hasRenderPass())===!1){let Le=C.opaque,Ie=C.transmissive;if(T.setupLights(),H.isArrayCamera){let De=H.cameras;if(Ie.length>0)for(let Ve=0,ot=De.length;Ve<ot;Ve++){let xt=De[Ve];Ai(Le,Ie,E,xt)}ut&&k.render(E);for(let Ve=0,ot=De.length;Ve<ot;Ve++){let xt=De[Ve];Vo(C,E,xt,xt.viewport)}}else Ie.length>0&&Ai(Le,Ie,E,H),ut&&k.render(E),Vo(C,E,H)}re!==null&&O===0&&(Je.updateMultisampleRenderTarget(re),Je.updateRenderTargetMipmap(re)),Z&&U.end(N),E.isScene===!0&&E.onAfterRender(N,E,H),Te.resetDefaultState(),X=-1,$=null,w.pop(),w.length>0?(T=w[w.length-1],Je.setTextureUnits(T.state.textureUnits),Ze===!0&&oe.setGlobalState(N.clippingPlanes,T.state.camera)):T=null,_.pop(),_.length>0?C=_[_.length-1]:C=null,G!==null&&G.renderEnd()};function ls(E,H,ee,Z){if(E.visible===!1)return;if(E.layers.test(H.layers)){if(E.isGroup)ee=E.renderOrder;else if(E.isLOD)E.autoUpdate===!0&&E.update(H);else if(E.isLight)T.pushLight(E),E.castShadow&&T.pushShadow(E);else if(E.isSprite){let Le=H.isArrayCamera?ke:fe;if(!E.frustumCulled||E.intersectsFrustum(Le)){Z&&et.setFromMatrixPosition(E.matrixWorld).applyMatrix4(wt);let Ie=de.update(E),De=E.material;De.visible&&C.push(E,Ie,De,ee,et.z,null,H)}}else if(E.isMesh||E.isLine||E.isPoints){let Le=H.isArrayCamera?ke:fe;if(!E.frustumCulled||E.intersectsFrustum(Le)){let Ie=de.update(E),De=E.material;if(Z&&(E.boundingSphere!==void 0?(E.boundingSphere===null&&E.computeBoundingSphere(),et.copy(E.boundingSphere.center)):(Ie.boundingSphere===null&&Ie.computeBoundingSphere(),et.copy(Ie.boundingSphere.center)),et.applyMatrix4(E.matrixWorld).applyMatrix4(wt)),Array.isArray(De)){let Ve=Ie.groups;for(let ot=0,xt=Ve.length;ot<xt;ot++){let He=Ve[ot],vt=De[He.materialIndex];vt&&vt.visible&&C.push(E,Ie,vt,ee,et.z,He,H)}}else De.visible&&C.push(E,Ie,De,ee,et.z,null,H)}}}let Ce=E.children;for(let Le=0,Ie=Ce.length;Le<Ie;Le++)ls(Ce[Le],H,ee,Z)}function Vo(E,H,ee,Z){let{opaque:K,transmissive:Ce,transparent:Le}=E;T.setupLightsView(ee),Ze===!0&&oe.setGlobalState(N.clippingPlanes,ee),Z&&Ae.viewport(W.copy(Z)),K.length>0&&on(K,H,ee),Ce.length>0&&on(Ce,H,ee),Le.length>0&&on(Le,H,ee),Ae.buffers.depth.setTest(!0),Ae.buffers.depth.setMask(!0),Ae.buffers.color.setMask(!0),Ae.setPolygonOffset(!1)}function Ai(E,H,ee,Z){if((ee.isScene===!0?ee.overrideMaterial:null)!==null)return;if(T.state.transmissionRenderTarget[Z.id]===void 0){let He=Ke.has("EXT_color_buffer_half_float")||Ke.has("EXT_color_buffer_float");T.state.transmissionRenderTarget[Z.id]=new _i(1,1,{generateMipmaps:!0,type:He?zi:xi,minFilter:Ts,samples:Math.max(4,dt.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:At.workingColorSpace})}let Ce=T.state.transmissionRenderTarget[Z.id],Le=Z.viewport||W;Ce.setSize(Le.z*N.transmissionResolutionScale,Le.w*N.transmissionResolutionScale);let Ie=N.getRenderTarget(),De=N.getActiveCubeFace(),Ve=N.getActiveMipmapLevel();N.setRenderTarget(Ce),N.getClearColor(Q),me=N.getClearAlpha(),me<1&&N.setClearColor(16777215,.5),N.clear(),ut&&k.render(ee);let ot=N.toneMapping;N.toneMapping=ss;let xt=Z.viewport;if(Z.viewport!==void 0&&(Z.viewport=void 0),T.setupLightsView(Z),Ze===!0&&oe.setGlobalState(N.clippingPlanes,Z),on(E,ee,Z),Je.updateMultisampleRenderTarget(Ce),Je.updateRenderTargetMipmap(Ce),Ke.has("WEBGL_multisampled_render_to_texture")===!1){let He=!1;for(let vt=0,nn=H.length;vt<nn;vt++){let Bt=H[vt],{object:kt,geometry:vn,material:Be,group:fn}=Bt;if(Be.side===is&&kt.layers.test(Z.layers)){let Et=Be.side;Be.side=Kn,Be.needsUpdate=!0,hn(kt,ee,Z,vn,Be,fn),Be.side=Et,Be.needsUpdate=!0,He=!0}}He===!0&&(Je.updateMultisampleRenderTarget(Ce),Je.updateRenderTargetMipmap(Ce))}N.setRenderTarget(Ie,De,Ve),N.setClearColor(Q,me),xt!==void 0&&(Z.viewport=xt),N.toneMapping=ot}function on(E,H,ee){let Z=H.isScene===!0?H.overrideMaterial:null;for(let K=0,Ce=E.length;K<Ce;K++){let Le=E[K],{object:Ie,geometry:De,group:Ve}=Le,ot=Le.material;ot.allowOverride===!0&&Z!==null&&(ot=Z),Ie.layers.test(ee.layers)&&hn(Ie,H,ee,De,ot,Ve)}}function hn(E,H,ee,Z,K,Ce){G!==null&&K.isNodeMaterial&&G.setObject(E,K),E.onBeforeRender(N,H,ee,Z,K,Ce),E.modelViewMatrix.multiplyMatrices(ee.matrixWorldInverse,E.matrixWorld),E.normalMatrix.getNormalMatrix(E.modelViewMatrix),K.onBeforeRender(N,H,ee,Z,E,Ce),K.transparent===!0&&K.side===is&&K.forceSinglePass===!1?(K.side=Kn,K.needsUpdate=!0,N.renderBufferDirect(ee,H,Z,K,E,Ce),K.side=ar,K.needsUpdate=!0,N.renderBufferDirect(ee,H,Z,K,E,Ce),K.side=is):N.renderBufferDirect(ee,H,Z,K,E,Ce),E.onAfterRender(N,H,ee,Z,K,Ce)}function un(E){let H=0;for(let ee of E)ee.texture!==null&&H++;return H}function Wi(E,H,ee){H.isScene!==!0&&(H=Ct);let Z=Xe.get(E),K=T.state.lights,Ce=T.state.shadowsArray,Le=K.state.version,Ie=ce.getParameters(E,K.state,Ce,H,ee,T.state.lightProbeGridArray),De=ce.getProgramCacheKey(Ie),Ve=Z.programs;Z.environment=E.isMeshStandardMaterial||E.isMeshLambertMaterial||E.isMeshPhongMaterial?H.environment:null,Z.fog=H.fog;let ot=E.isMeshStandardMaterial||E.isMeshLambertMaterial&&!E.envMap||E.isMeshPhongMaterial&&!E.envMap;Z.envMap=I.get(E.envMap||Z.environment,ot),Z.envMapRotation=Z.environment!==null&&E.envMap===null?H.environmentRotation:E.envMapRotation,Ve===void 0&&(E.addEventListener("dispose",mt),Ve=new Map,Z.programs=Ve,Z.programVariants=new Map);let xt=Ve.get(De);if(xt!==void 0){if(Z.currentProgram===xt&&Z.lightsStateVersion===Le)return Wo(E,Ie),xt}else Ie.uniforms=ce.getUniforms(E),G!==null&&E.isNodeMaterial&&G.build(E,ee,Ie),E.onBeforeCompile(Ie,N),xt=ce.acquireProgram(Ie,De),Ve.set(De,xt),Z.uniforms=Ie.uniforms;let He=Z.uniforms;return(!E.isShaderMaterial&&!E.isRawShaderMaterial||E.clipping===!0)&&(He.clippingPlanes=oe.uniform),Wo(E,Ie),Z.needsLights=Ps(E),Z.lightsStateVersion=Le,Z.needsLights&&(He.ambientLightColor.value=K.state.ambient,He.lightProbe.value=K.state.probe,He.sunLights.value=K.state.sun,He.sunLightShadows.value=K.state.sunShadow,He.directionalLights.value=K.state.directional,He.directionalLightShadows.value=K.state.directionalShadow,He.spotLights.value=K.state.spot,He.spotLightShadows.value=K.state.spotShadow,He.rectAreaLights.value=K.state.rectArea,He.ltc_1.value=K.state.rectAreaLTC1,He.ltc_2.value=K.state.rectAreaLTC2,He.pointLights.value=K.state.point,He.pointLightShadows.value=K.state.pointShadow,He.hemisphereLights.value=K.state.hemi,He.sunShadowMatrix.value=K.state.sunShadowMatrix,He.sunShadowCascade.value=K.state.sunShadowCascade,He.directionalShadowMatrix.value=K.state.directionalShadowMatrix,He.spotLightMatrix.value=K.state.spotLightMatrix,He.spotLightMap.value=K.state.spotLightMap,He.pointShadowMatrix.value=K.state.pointShadowMatrix),Z.numLightProbeGrids=un(T.state.lightProbeGridArray),Z.currentProgram=xt,Z.uniformsList=null,xt}function ii(E,H,ee,Z,K){let Ce=Xe.get(E),Le=Ce.currentProgram.id+","+Z+","+K,Ie=Ce.programVariants.get(Le);return Ie===void 0?(Ie=Wi(E,H,ee),Ce.programVariants.set(Le,Ie)):(Ce.currentProgram=Ie,Ce.uniformsList=null,Ce.outputColorSpace=Z,Ce.toneMapping=K),Ie}function Is(E){if(E.uniformsList===null){let H=E.currentProgram.getUniforms();E.uniformsList=zo.seqWithValue(H.seq,E.uniforms)}return E.uniformsList}function Wo(E,H){let ee=Xe.get(E);ee.outputColorSpace=H.outputColorSpace,ee.batching=H.batching,ee.batchingColor=H.batchingColor,ee.instancing=H.instancing,ee.instancingColor=H.instancingColor,ee.instancingMorph=H.instancingMorph,ee.skinning=H.skinning,ee.morphTargets=H.morphTargets,ee.morphNormals=H.morphNormals,ee.morphColors=H.morphColors,ee.morphTargetsCount=H.morphTargetsCount,ee.numClippingPlanes=H.numClippingPlanes,ee.numIntersection=H.numClipIntersection,ee.vertexAlphas=H.vertexAlphas,ee.vertexTangents=H.vertexTangents,ee.toneMapping=H.toneMapping}function Xo(E,H,ee,Z,K){H.isScene!==!0&&(H=Ct),Je.resetTextureUnits();let Ce=H.fog,Le=Z.isMeshStandardMaterial||Z.isMeshLambertMaterial||Z.isMeshPhongMaterial?H.environment:null,Ie=re===null?N.outputColorSpace:re.isXRRenderTarget===!0?re.texture.colorSpace:At.workingColorSpace,De=Z.isMeshStandardMaterial||Z.isMeshLambertMaterial&&!Z.envMap||Z.isMeshPhongMaterial&&!Z.envMap,Ve=I.get(Z.envMap||Le,De),ot=Z.vertexColors===!0&&!!ee.attributes.color&&ee.attributes.color.itemSize===4,xt=!!ee.attributes.tangent&&(!!Z.normalMap||Z.anisotropy>0),He=!!ee.morphAttributes.position,vt=!!ee.morphAttributes.normal,nn=!!ee.morphAttributes.color,Bt=ss;Z.toneMapped&&(re===null||re.isXRRenderTarget===!0)&&(Bt=N.toneMapping);let kt=ee.morphAttributes.position||ee.morphAttributes.normal||ee.morphAttributes.color,vn=kt!==void 0?kt.length:0,Be=Xe.get(Z),fn=T.state.lights;if(Ze===!0&&(Rt===!0||E!==$)){let zt=E===$&&Z.id===X;oe.setState(Z,E,zt)}let Et=!1,cs=!1;Z.version===Be.__version?Be.needsLights&&Be.lightsStateVersion!==fn.state.version||K.isBatchedMesh&&Be.batching===!1||!K.isBatchedMesh&&Be.batching===!0||K.isBatchedMesh&&Be.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&Be.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&Be.instancing===!1||!K.isInstancedMesh&&Be.instancing===!0||K.isSkinnedMesh&&Be.skinning===!1||!K.isSkinnedMesh&&Be.skinning===!0||K.isInstancedMesh&&Be.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&Be.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&Be.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&Be.instancingMorph===!1&&K.morphTexture!==null||Be.envMap!==Ve||Z.fog===!0&&Be.fog!==Ce||Be.numClippingPlanes!==void 0&&(Be.numClippingPlanes!==oe.numPlanes||Be.numIntersection!==oe.numIntersection)||Be.vertexAlphas!==ot||Be.vertexTangents!==xt||Be.morphTargets!==He||Be.morphNormals!==vt||Be.morphColors!==nn||Be.morphTargetsCount!==vn||Be.numLightProbeGrids!==un(T.state.lightProbeGridArray)?Et=!0:(Be.outputColorSpace!==Ie||Be.toneMapping!==Bt)&&(cs=!0):(Et=!0,Be.__version=Z.version);let dn=Be.currentProgram;(Et===!0||cs===!0)&&(dn=cs===!0?ii(Z,H,K,Ie,Bt):Wi(Z,H,K),G&&Z.isNodeMaterial&&G.onUpdateProgram(Z,dn,Be));let zr=!1,Xi=!1,hs=!1,gt=dn.getUniforms(),an=Be.uniforms;if(Ae.useProgram(dn.program)&&(zr=!0,Xi=!0,hs=!0),Z.id!==X&&(X=Z.id,Xi=!0),zr||$!==E){Ae.buffers.depth.getReversed()&&E.reversedDepth!==!0&&(E._reversedDepth=!0,E.updateProjectionMatrix()),gt.setValue(F,"projectionMatrix",E.projectionMatrix),gt.setValue(F,"viewMatrix",E.matrixWorldInverse);let pn=gt.map.cameraPosition;pn!==void 0&&pn.setValue(F,Vt.setFromMatrixPosition(E.matrixWorld)),dt.logarithmicDepthBuffer&&gt.setValue(F,"logDepthBufFC",2/(Math.log(E.far+1)/Math.LN2)),(Z.isMeshPhongMaterial||Z.isMeshToonMaterial||Z.isMeshLambertMaterial||Z.isMeshBasicMaterial||Z.isMeshStandardMaterial||Z.isShaderMaterial)&&gt.setValue(F,"isOrthographic",E.isOrthographicCamera===!0),$!==E&&($=E,Xi=!0,hs=!0)}if(Be.needsLights&&(fn.state.sunShadowMap.length>0&&gt.setValue(F,"sunShadowMap",fn.state.sunShadowMap,Je),fn.state.directionalShadowMap.length>0&&gt.setValue(F,"directionalShadowMap",fn.state.directionalShadowMap,Je),fn.state.spotShadowMap.length>0&&gt.setValue(F,"spotShadowMap",fn.state.spotShadowMap,Je),fn.state.pointShadowMap.length>0&&gt.setValue(F,"pointShadowMap",fn.state.pointShadowMap,Je)),K.isSkinnedMesh){gt.setOptional(F,K,"bindMatrix"),gt.setOptional(F,K,"bindMatrixInverse");let zt=K.skeleton;zt&&(zt.boneTexture===null&&zt.computeBoneTexture(),gt.setValue(F,"boneTexture",zt.boneTexture,Je))}K.isBatchedMesh&&(gt.setOptional(F,K,"batchingTexture"),gt.setValue(F,"batchingTexture",K._matricesTexture,Je),gt.setOptional(F,K,"batchingIdTexture"),gt.setValue(F,"batchingIdTexture",K._indirectTexture,Je),gt.setOptional(F,K,"batchingColorTexture"),K._colorsTexture!==null&&gt.setValue(F,"batchingColorTexture",K._colorsTexture,Je));let Vn=ee.morphAttributes;if((Vn.position!==void 0||Vn.normal!==void 0||Vn.color!==void 0)&&ae.update(K,ee,dn),(Xi||Be.receiveShadow!==K.receiveShadow)&&(Be.receiveShadow=K.receiveShadow,gt.setValue(F,"receiveShadow",K.receiveShadow)),(Z.isMeshStandardMaterial||Z.isMeshLambertMaterial||Z.isMeshPhongMaterial)&&Z.envMap===null&&H.environment!==null&&(an.envMapIntensity.value=H.environmentIntensity),an.dfgLUT!==void 0&&(an.dfgLUT.value=eT()),Xi){if(gt.setValue(F,"toneMappingExposure",N.toneMappingExposure),Be.needsLights&&Br(an,hs),Ce&&Z.fog===!0&&Me.refreshFogUniforms(an,Ce),Me.refreshMaterialUniforms(an,Z,xe,be,T.state.transmissionRenderTarget[E.id]),Be.needsLights&&Be.numLightProbeGrids>0){let zt=S,pn=0;for(let Fn of T.state.lightProbeGridArray)Fn.texture!==null&&(zt.textures[pn]=Fn.texture,zt.min[pn]=Fn.boundingBox.min,zt.max[pn]=Fn.boundingBox.max,zt.resolution[pn]=Fn.resolution,pn++);for(let Fn in zt)zt[Fn].length=pn;an.probesSH.value=zt.textures,an.probesMin.value=zt.min,an.probesMax.value=zt.max,an.probesResolution.value=zt.resolution}zo.upload(F,Is(Be),an,Je)}if(Z.isShaderMaterial&&Z.uniformsNeedUpdate===!0&&(zo.upload(F,Is(Be),an,Je),Z.uniformsNeedUpdate=!1),Z.isSpriteMaterial&&gt.setValue(F,"center",K.center),gt.setValue(F,"modelViewMatrix",K.modelViewMatrix),gt.setValue(F,"normalMatrix",K.normalMatrix),gt.setValue(F,"modelMatrix",K.matrixWorld),Z.uniformsGroups!==void 0){let zt=Z.uniformsGroups;for(let pn=0,Fn=zt.length;pn<Fn;pn++){let rl=zt[pn];$e.update(rl,dn),$e.bind(rl,dn)}}return dn}function Br(E,H){E.ambientLightColor.needsUpdate=H,E.lightProbe.needsUpdate=H,E.sunLights.needsUpdate=H,E.sunLightShadows.needsUpdate=H,E.directionalLights.needsUpdate=H,E.directionalLightShadows.needsUpdate=H,E.pointLights.needsUpdate=H,E.pointLightShadows.needsUpdate=H,E.spotLights.needsUpdate=H,E.spotLightShadows.needsUpdate=H,E.rectAreaLights.needsUpdate=H,E.hemisphereLights.needsUpdate=H}function Ps(E){return E.isMeshLambertMaterial||E.isMeshToonMaterial||E.isMeshPhongMaterial||E.isMeshStandardMaterial||E.isShadowMaterial||E.isShaderMaterial&&E.lights===!0}this.getActiveCubeFace=function(){return q},this.getActiveMipmapLevel=function(){return O},this.getRenderTarget=function(){return re},this.setRenderTargetTextures=function(E,H,ee){let Z=Xe.get(E);Z.__autoAllocateDepthBuffer=E.resolveDepthBuffer===!1,Z.__autoAllocateDepthBuffer===!1&&(Z.__useRenderToTexture=!1),Xe.get(E.texture).__webglTexture=H,Xe.get(E.depthTexture).__webglTexture=Z.__autoAllocateDepthBuffer?void 0:ee,Z.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(E,H){let ee=Xe.get(E);ee.__webglFramebuffer=H,ee.__useDefaultFramebuffer=H===void 0},this.setRenderTarget=function(E,H=0,ee=0){re=E,q=H,O=ee;let Z=null,K=!1,Ce=!1;if(E){let Ie=Xe.get(E);if(Ie.__useDefaultFramebuffer!==void 0){Ae.bindFramebuffer(F.FRAMEBUFFER,Ie.__webglFramebuffer),W.copy(E.viewport),ne.copy(E.scissor),le=E.scissorTest,Ae.viewport(W),Ae.scissor(ne),Ae.setScissorTest(le),X=-1;return}else if(Ie.__webglFramebuffer===void 0)Je.setupRenderTarget(E);else if(Ie.__hasExternalTextures)Je.rebindTextures(E,Xe.get(E.texture).__webglTexture,Xe.get(E.depthTexture).__webglTexture);else if(E.depthBuffer){let ot=E.depthTexture;if(Ie.__boundDepthTexture!==ot){if(ot!==null&&Xe.has(ot)&&(E.width!==ot.image.width||E.height!==ot.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Je.setupDepthRenderbuffer(E)}}let De=E.texture;(De.isData3DTexture||De.isDataArrayTexture||De.isCompressedArrayTexture)&&(Ce=!0);let Ve=Xe.get(E).__webglFramebuffer;E.isWebGLCubeRenderTarget?(Array.isArray(Ve[H])?Z=Ve[H][ee]:Z=Ve[H],K=!0):E.samples>0&&Je.useMultisampledRTT(E)===!1?Z=Xe.get(E).__webglMultisampledFramebuffer:Array.isArray(Ve)?Z=Ve[ee]:Z=Ve,W.copy(E.viewport),ne.copy(E.scissor),le=E.scissorTest}else W.copy(Ne).multiplyScalar(xe).floor(),ne.copy(qe).multiplyScalar(xe).floor(),le=tt;if(ee!==0&&(Z=B),Ae.bindFramebuffer(F.FRAMEBUFFER,Z)&&Ae.drawBuffers(E,Z),Ae.viewport(W),Ae.scissor(ne),Ae.setScissorTest(le),K){let Ie=Xe.get(E.texture);F.framebufferTexture2D(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_CUBE_MAP_POSITIVE_X+H,Ie.__webglTexture,ee)}else if(Ce){let Ie=H;for(let De=0;De<E.textures.length;De++){let Ve=Xe.get(E.textures[De]);F.framebufferTextureLayer(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0+De,Ve.__webglTexture,ee,Ie)}}else if(E!==null&&ee!==0){let Ie=Xe.get(E.texture);F.framebufferTexture2D(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_2D,Ie.__webglTexture,ee)}X=-1};function kr(E){let H=Xe.get(E);return(H.__readFormat!==E.format||H.__readType!==E.type)&&(H.__readFormat=E.format,H.__readType=E.type,H.__formatReadable=dt.textureFormatReadable(E.format),H.__typeReadable=dt.textureTypeReadable(E.type)),H}this.readRenderTargetPixels=function(E,H,ee,Z,K,Ce,Le,Ie=0){if(!(E&&E.isWebGLRenderTarget)){at("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let De=Xe.get(E).__webglFramebuffer;if(E.isWebGLCubeRenderTarget&&Le!==void 0&&(De=De[Le],Array.isArray(De)&&(De=De[0])),De){Ae.bindFramebuffer(F.FRAMEBUFFER,De);try{let Ve=E.textures[Ie],ot=Ve.format,xt=Ve.type;E.textures.length>1&&F.readBuffer(F.COLOR_ATTACHMENT0+Ie);let He=kr(Ve);if(He.__formatReadable===!1){at("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(He.__typeReadable===!1){at("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}H>=0&&H<=E.width-Z&&ee>=0&&ee<=E.height-K&&F.readPixels(H,ee,Z,K,Se.convert(ot),Se.convert(xt),Ce)}finally{let Ve=re!==null?Xe.get(re).__webglFramebuffer:null;Ae.bindFramebuffer(F.FRAMEBUFFER,Ve)}}},this.readRenderTargetPixelsAsync=async function(E,H,ee,Z,K,Ce,Le,Ie=0){if(!(E&&E.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let De=Xe.get(E).__webglFramebuffer;if(E.isWebGLCubeRenderTarget&&Le!==void 0&&(De=De[Le],Array.isArray(De)&&(De=De[0])),De)if(H>=0&&H<=E.width-Z&&ee>=0&&ee<=E.height-K){Ae.bindFramebuffer(F.FRAMEBUFFER,De);let Ve=E.textures[Ie],ot=Ve.format,xt=Ve.type;E.textures.length>1&&F.readBuffer(F.COLOR_ATTACHMENT0+Ie);let He=kr(Ve);if(He.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(He.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let vt=F.createBuffer();F.bindBuffer(F.PIXEL_PACK_BUFFER,vt),F.bufferData(F.PIXEL_PACK_BUFFER,Ce.byteLength,F.STREAM_READ),F.readPixels(H,ee,Z,K,Se.convert(ot),Se.convert(xt),0),F.bindBuffer(F.PIXEL_PACK_BUFFER,null);let nn=re!==null?Xe.get(re).__webglFramebuffer:null;Ae.bindFramebuffer(F.FRAMEBUFFER,nn);let Bt=F.fenceSync(F.SYNC_GPU_COMMANDS_COMPLETE,0);return F.flush(),await N0(F,Bt,4),F.bindBuffer(F.PIXEL_PACK_BUFFER,vt),F.getBufferSubData(F.PIXEL_PACK_BUFFER,0,Ce),F.bindBuffer(F.PIXEL_PACK_BUFFER,null),F.deleteBuffer(vt),F.deleteSync(Bt),Ce}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(E,H=null,ee=0){let Z=Math.pow(2,-ee),K=Math.floor(E.image.width*Z),Ce=Math.floor(E.image.height*Z),Le=H!==null?H.x:0,Ie=H!==null?H.y:0;Je.setTexture2D(E,0),F.copyTexSubImage2D(F.TEXTURE_2D,ee,0,0,Le,Ie,K,Ce),Ae.unbindTexture()},this.copyTextureToTexture=function(E,H,ee=null,Z=null,K=0,Ce=0){let Le,Ie,De,Ve,ot,xt,He,vt,nn,Bt=E.isCompressedTexture?E.mipmaps[Ce]:E.image;if(ee!==null)Le=ee.max.x-ee.min.x,Ie=ee.max.y-ee.min.y,De=ee.isBox3?ee.max.z-ee.min.z:1,Ve=ee.min.x,ot=ee.min.y,xt=ee.isBox3?ee.min.z:0;else{let gt=Math.pow(2,-K);Le=Math.floor(Bt.width*gt),Ie=Math.floor(Bt.height*gt),E.isDataArrayTexture?De=Bt.depth:E.isData3DTexture?De=Math.floor(Bt.depth*gt):De=1,Ve=0,ot=0,xt=0}Z!==null?(He=Z.x,vt=Z.y,nn=Z.z):(He=0,vt=0,nn=0);let kt=Se.convert(H.format),vn=Se.convert(H.type),Be;H.isData3DTexture?(Je.setTexture3D(H,0),Be=F.TEXTURE_3D):H.isDataArrayTexture||H.isCompressedArrayTexture?(Je.setTexture2DArray(H,0),Be=F.TEXTURE_2D_ARRAY):(Je.setTexture2D(H,0),Be=F.TEXTURE_2D),Ae.activeTexture(F.TEXTURE0),Ae.pixelStorei(F.UNPACK_FLIP_Y_WEBGL,H.flipY),Ae.pixelStorei(F.UNPACK_PREMULTIPLY_ALPHA_WEBGL,H.premultiplyAlpha),Ae.pixelStorei(F.UNPACK_ALIGNMENT,H.unpackAlignment);let fn=Ae.getParameter(F.UNPACK_ROW_LENGTH),Et=Ae.getParameter(F.UNPACK_IMAGE_HEIGHT),cs=Ae.getParameter(F.UNPACK_SKIP_PIXELS),dn=Ae.getParameter(F.UNPACK_SKIP_ROWS),zr=Ae.getParameter(F.UNPACK_SKIP_IMAGES);Ae.pixelStorei(F.UNPACK_ROW_LENGTH,Bt.width),Ae.pixelStorei(F.UNPACK_IMAGE_HEIGHT,Bt.height),Ae.pixelStorei(F.UNPACK_SKIP_PIXELS,Ve),Ae.pixelStorei(F.UNPACK_SKIP_ROWS,ot),Ae.pixelStorei(F.UNPACK_SKIP_IMAGES,xt);let Xi=E.isDataArrayTexture||E.isData3DTexture,hs=H.isDataArrayTexture||H.isData3DTexture;if(E.isDepthTexture){let gt=Xe.get(E),an=Xe.get(H),Vn=Xe.get(gt.__renderTarget),zt=Xe.get(an.__renderTarget);Ae.bindFramebuffer(F.READ_FRAMEBUFFER,Vn.__webglFramebuffer),Ae.bindFramebuffer(F.DRAW_FRAMEBUFFER,zt.__webglFramebuffer);for(let pn=0;pn<De;pn++)Xi&&(F.framebufferTextureLayer(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,Xe.get(E).__webglTexture,K,xt+pn),F.framebufferTextureLayer(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,Xe.get(H).__webglTexture,Ce,nn+pn)),F.blitFramebuffer(Ve,ot,Ve+Le,ot+Ie,He,vt,He+Le,vt+Ie,F.DEPTH_BUFFER_BIT,F.NEAREST);Ae.bindFramebuffer(F.READ_FRAMEBUFFER,null),Ae.bindFramebuffer(F.DRAW_FRAMEBUFFER,null)}else if(K!==0||E.isRenderTargetTexture||Xe.has(E)){let gt=Xe.get(E),an=Xe.get(H);Ae.bindFramebuffer(F.READ_FRAMEBUFFER,L),Ae.bindFramebuffer(F.DRAW_FRAMEBUFFER,z);for(let Vn=0;Vn<De;Vn++)Xi?F.framebufferTextureLayer(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,gt.__webglTexture,K,xt+Vn):F.framebufferTexture2D(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_2D,gt.__webglTexture,K),hs?F.framebufferTextureLayer(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,an.__webglTexture,Ce,nn+Vn):F.framebufferTexture2D(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_2D,an.__webglTexture,Ce),K!==0?F.blitFramebuffer(Ve,ot,Ve+Le,ot+Ie,He,vt,He+Le,vt+Ie,F.COLOR_BUFFER_BIT,F.NEAREST):hs?F.copyTexSubImage3D(Be,Ce,He,vt,nn+Vn,Ve,ot,Le,Ie):F.copyTexSubImage2D(Be,Ce,He,vt,Ve,ot,Le,Ie);Ae.bindFramebuffer(F.READ_FRAMEBUFFER,null),Ae.bindFramebuffer(F.DRAW_FRAMEBUFFER,null)}else hs?E.isDataTexture||E.isData3DTexture?F.texSubImage3D(Be,Ce,He,vt,nn,Le,Ie,De,kt,vn,Bt.data):H.isCompressedArrayTexture?F.compressedTexSubImage3D(Be,Ce,He,vt,nn,Le,Ie,De,kt,Bt.data):F.texSubImage3D(Be,Ce,He,vt,nn,Le,Ie,De,kt,vn,Bt):E.isDataTexture?F.texSubImage2D(F.TEXTURE_2D,Ce,He,vt,Le,Ie,kt,vn,Bt.data):E.isCompressedTexture?F.compressedTexSubImage2D(F.TEXTURE_2D,Ce,He,vt,Bt.width,Bt.height,kt,Bt.data):F.texSubImage2D(F.TEXTURE_2D,Ce,He,vt,Le,Ie,kt,vn,Bt);Ae.pixelStorei(F.UNPACK_ROW_LENGTH,fn),Ae.pixelStorei(F.UNPACK_IMAGE_HEIGHT,Et),Ae.pixelStorei(F.UNPACK_SKIP_PIXELS,cs),Ae.pixelStorei(F.UNPACK_SKIP_ROWS,dn),Ae.pixelStorei(F.UNPACK_SKIP_IMAGES,zr),Ce===0&&H.generateMipmaps===!0&&H.mipmapsAutoUpdate===!0&&F.generateMipmap(Be),Ae.unbindTexture()},this.initRenderTarget=function(E){Xe.get(E).__webglFramebuffer===void 0&&Je.setupRenderTarget(E)},this.initTexture=function(E){E.isCubeTexture?Je.setTextureCube(E,0):E.isData3DTexture?Je.setTexture3D(E,0):E.isDataArrayTexture||E.isCompressedArrayTexture?Je.setTexture2DArray(E,0):Je.setTexture2D(E,0),Ae.unbindTexture()},this.resetState=function(){q=0,O=0,re=null,Ae.reset(),Te.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Ti}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorSpace=At._getDrawingBufferColorSpace(e),t.unpackColorSpace=At._getUnpackColorSpace()}};var x_={type:"change"},Id={type:"start"},b_={type:"end"},Xh=new tr,v_=new pi,nT=Math.cos(70*cd.DEG2RAD),En=new J,ni=2*Math.PI,Ut={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Cd=1e-6,$h=class extends Va{constructor(e,t=null){super(e,t),this.state=Ut.NONE,this.target=new J,this.cursor=new J,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:rr.ROTATE,MIDDLE:rr.DOLLY,RIGHT:rr.PAN},this.touches={ONE:or.ROTATE,TWO:or.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new J,this._lastQuaternion=new gi,this._lastTargetPosition=new J,this._quat=new gi().setFromUnitVectors(e.up,new J(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Do,this._sphericalDelta=new Do,this._scale=1,this._panOffset=new J,this._rotateStart=new pt,this._rotateEnd=new pt,this._rotateDelta=new pt,this._panStart=new pt,this._panEnd=new pt,this._panDelta=new pt,this._dollyStart=new pt,this._dollyEnd=new pt,this._dollyDelta=new pt,this._dollyDirection=new J,this._mouse=new pt,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=sT.bind(this),this._onPointerDown=iT.bind(this),this._onPointerUp=rT.bind(this),this._onContextMenu=fT.bind(this),this._onMouseWheel=lT.bind(this),this._onKeyDown=cT.bind(this),this._onTouchStart=hT.bind(this),this._onTouchMove=uT.bind(this),this._onMouseDown=oT.bind(this),this._onMouseMove=aT.bind(this),this._interceptControlDown=dT.bind(this),this._interceptControlUp=pT.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Ut.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(x_),this.update(),this.state=Ut.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){let t=this.object.position;En.copy(t).sub(this.target),En.applyQuaternion(this._quat),this._spherical.setFromVector3(En),this.autoRotate&&this.state===Ut.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(i)&&isFinite(s)&&(i<-Math.PI?i+=ni:i>Math.PI&&(i-=ni),s<-Math.PI?s+=ni:s>Math.PI&&(s-=ni),i<=s?this._spherical.theta=Math.max(i,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+s)/2?Math.max(i,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let o=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=o!=this._spherical.radius}if(En.setFromSpherical(this._spherical),En.applyQuaternion(this._quatInverse),t.copy(this.target).add(En),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let o=null;if(this.object.isPerspectiveCamera){let a=En.length();o=this._clampDistance(a*this._scale);let l=a-o;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){let a=new J(this._mouse.x,this._mouse.y,0);a.unproject(this.object);let l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;let c=new J(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(a),this.object.updateMatrixWorld(),o=En.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;o!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(o).add(this.object.position):(Xh.origin.copy(this.object.position),Xh.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(Xh.direction))<nT?this.object.lookAt(this.target):(v_.setFromNormalAndCoplanarPoint(this.object.up,this.target),Xh.intersectPlane(v_,this.target))))}else if(this.object.isOrthographicCamera){let o=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),o!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>Cd||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Cd||this._lastTargetPosition.distanceToSquared(this.target)>Cd?(this.dispatchEvent(x_),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?ni/60*this.autoRotateSpeed*e:ni/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){En.setFromMatrixColumn(t,0),En.multiplyScalar(-e),this._panOffset.add(En)}_panUp(e,t){this.screenSpacePanning===!0?En.setFromMatrixColumn(t,1):(En.setFromMatrixColumn(t,0),En.crossVectors(this.object.up,En)),En.multiplyScalar(e),this._panOffset.add(En)}_pan(e,t){let i=this.domElement;if(this.object.isPerspectiveCamera){let s=this.object.position;En.copy(s).sub(this.target);let r=En.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/i.clientHeight,this.object.matrix),this._panUp(2*t*r/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let i=this.domElement.getBoundingClientRect(),s=e-i.left,r=t-i.top,o=i.width,a=i.height;this._mouse.x=s/o*2-1,this._mouse.y=-(r/a)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ni*this._rotateDelta.x/t.clientHeight),this._rotateUp(ni*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(ni*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-ni*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(ni*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-ni*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(i,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(i,s)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let i=this._getSecondPointerPosition(e),s=.5*(e.pageX+i.x),r=.5*(e.pageY+i.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ni*this._rotateDelta.x/t.clientHeight),this._rotateUp(ni*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(i,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let o=(e.pageX+t.x)*.5,a=(e.pageY+t.y)*.5;this._updateZoomParameters(o,a)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new pt,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,i={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}};function iT(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function sT(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function rT(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(b_),this.state=Ut.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function oT(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case rr.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=Ut.DOLLY;break;case rr.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Ut.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Ut.ROTATE}break;case rr.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Ut.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Ut.PAN}break;default:this.state=Ut.NONE}this.state!==Ut.NONE&&this.dispatchEvent(Id)}function aT(n){switch(this.state){case Ut.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case Ut.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case Ut.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function lT(n){this.enabled===!1||this.enableZoom===!1||this.state!==Ut.NONE||(n.preventDefault(),this.dispatchEvent(Id),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(b_))}function cT(n){this.enabled!==!1&&this._handleKeyDown(n)}function hT(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case or.ROTATE:if(this.enableRotate===!1){this.state=Ut.NONE;break}this._handleTouchStartRotate(n),this.state=Ut.TOUCH_ROTATE;break;case or.PAN:if(this.enablePan===!1){this.state=Ut.NONE;break}this._handleTouchStartPan(n),this.state=Ut.TOUCH_PAN;break;default:this.state=Ut.NONE}break;case 2:switch(this.touches.TWO){case or.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=Ut.TOUCH_DOLLY_PAN;break;case or.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=Ut.TOUCH_DOLLY_ROTATE;break;default:this.state=Ut.NONE}break;default:this.state=Ut.NONE}this.state!==Ut.NONE&&this.dispatchEvent(Id)}function uT(n){switch(this._trackPointer(n),this.state){case Ut.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case Ut.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case Ut.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case Ut.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=Ut.NONE}}function fT(n){this.enabled!==!1&&n.preventDefault()}function dT(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function pT(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var qh=256,Pd=(()=>{let n=new Float32Array(qh*3),e=new _t;for(let t=0;t<qh;t++)e.setHSL(.66*(1-t/(qh-1)),.9,.55),n.set([e.r,e.g,e.b],t*3);return n})(),Yh=class{constructor(e){this.parent=e;this.renderer=new Hh({antialias:!1,preserveDrawingBuffer:!0}),this.renderer.setPixelRatio(Math.min(window.devicePixelRatio||1,2)),this.renderer.setClearColor(725014),e.appendChild(this.renderer.domElement),this.camera=new Yn(60,1,.05,200),this.camera.up.set(0,0,1),this.camera.position.set(-8,-8,7),this.controls=new $h(this.camera,this.renderer.domElement),this.controls.addEventListener("change",()=>this.dirty=!0),this.points=new Da(this.geometry,new Po({size:.06,vertexColors:!0})),this.points.frustumCulled=!1,this.scene.add(this.points);let t=new Ga(20,20,3885658,1844785);t.rotation.x=Math.PI/2,this.scene.add(t,new Ha(1)),this.ro=new ResizeObserver(()=>this.resize()),this.ro.observe(e);let i=()=>{this.dirty&&this.render(),this.raf=requestAnimationFrame(i)};this.raf=requestAnimationFrame(i)}parent;renderer;scene=new Ia;camera;controls;geometry=new ti;points;capacity=0;cloud;dirty=!0;raf=0;ro;colourBy="height";onShown=null;pending=!1;pendingStamp=null;lastCount=0;resize(){let e=this.parent.clientWidth,t=Math.max(200,this.parent.clientHeight-4);this.renderer.setSize(e,t,!0),this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.dirty=!0}show(e){let t=performance.now();this.cloud=Gp(e,this.cloud);let i=this.cloud.count;i>this.capacity&&(this.capacity=Math.max(i,Math.ceil(this.capacity*1.5)),this.geometry.setAttribute("position",new mi(new Float32Array(this.capacity*3),3)),this.geometry.setAttribute("color",new mi(new Float32Array(this.capacity*3),3)));let s=this.geometry.getAttribute("position"),r=this.geometry.getAttribute("color");return s.array.set(this.cloud.positions.subarray(0,i*3)),this.colour(this.cloud,r.array,i),s.needsUpdate=!0,r.needsUpdate=!0,this.geometry.setDrawRange(0,i),this.lastCount=i,this.pending=!0,this.pendingStamp=Rl(e.header),It.busyMs.cloudUnpack+=performance.now()-t,this.dirty=!0,i}colour(e,t,i){let s=this.colourBy==="intensity"&&i>0&&!Number.isNaN(e.intensity[0]),r=1/0,o=-1/0;for(let l=0;l<i;l++){let c=s?e.intensity[l]:e.positions[l*3+2];c<r&&(r=c),c>o&&(o=c)}let a=(qh-1)/(o>r?o-r:1);for(let l=0;l<i;l++){let c=Math.round(((s?e.intensity[l]:e.positions[l*3+2])-r)*a)*3;t[l*3]=Pd[c],t[l*3+1]=Pd[c+1],t[l*3+2]=Pd[c+2]}}render(){this.dirty=!1;let e=performance.now();this.renderer.render(this.scene,this.camera),It.busyMs.cloudRender+=performance.now()-e,this.pending&&this.onShown&&this.onShown(this.pendingStamp),this.pending=!1}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.controls.dispose(),this.geometry.dispose(),this.points.material.dispose(),this.renderer.dispose(),this.renderer.domElement.remove()}};function S_(n,e,t,i){let s=te("pre","config-effective","…"),r=te("div","config-changes"),o=te("textarea","config-editor");o.rows=8,o.spellcheck=!1,o.placeholder=`topics:
  /scan: { rate_limit_hz: 2 }`;let a=te("div","config-result"),l=In("apply change","",()=>{v()}),c=In("reload","small",()=>{g()}),h=te("div","config-controls");h.append(l,c);let f=te("div","config-edit");f.append(te("label","","change (YAML or JSON, the agent file's fields; only those listed below may change while it runs)"),o,h,a),n.append(r,f,s);let u=!0;function m(d){i.loaded=!0,i.mayChange=d.may_change,i.overlay=d.overlay??null,s.textContent=d.effective??d.error??"";let p=d.overlay??{},x=Object.keys(p).length,A=d.changed_by?` by ${d.changed_by}${d.changed_at_ms?`, ${new Date(d.changed_at_ms).toLocaleString()}`:""}`:"";r.textContent=x?`changes in force${A}:`:"no changes in force: the robot runs its file's configuration",x&&r.appendChild(te("pre","",JSON.stringify(p,null,2))),d.kept&&r.appendChild(te("div","info",`the hub keeps them and applies them again when ${t} reconnects (last by ${d.kept.by})`)),e.textContent=d.online?d.persisted?` · kept on the robot in ${d.persisted}`:" · not kept on the robot":" · offline",f.hidden=!d.may_change,l.disabled=!d.online,d.changeable&&(o.title=`may change while it runs: ${d.changeable.join(", ")}`),!o.value&&x&&(o.value=JSON.stringify(p,null,2))}async function g(){try{let d=await gn(`/api/v1/robots/${encodeURIComponent(t)}/config`);u&&m(d)}catch(d){if(!u)return;i.loaded=!0,s.textContent=`cannot read the configuration: ${d.message}`,f.hidden=!0}}async function v(){l.disabled=!0,a.className="config-result";try{let d=await gn(`/api/v1/robots/${encodeURIComponent(t)}/config`,{method:"PUT",body:o.value}),p=d.unchanged?"nothing changed":`applied: ${(d.changed??[]).join(", ")}`;a.textContent=p,a.classList.add("ok"),i.result=p,m({...d,may_change:!0,online:!0})}catch(d){let p=d instanceof dr?d.message:`${d.message}`;a.textContent=`refused: ${p}`,a.classList.add("error"),i.result=`refused: ${p}`}finally{l.disabled=!1}}return g(),()=>{u=!1}}function Or(n,e,t,i){(n instanceof HTMLButtonElement||n instanceof HTMLSelectElement)&&(n.disabled=!0),n.title=t,i.textContent=`Disabled: ${t}`,i.className="why",It.disabled[e]=t}function M_(n,e,t,i,s,r){let o=`/${t}/`,a=te("div","task nav");a.appendChild(te("h3","","Navigation goal"));let l=te("p","muted","Looking for the robot's navigation action…"),c=te("progress");c.max=1,c.value=0;let h=te("div","navstate",""),f=In("Cancel goal","danger");f.disabled=!0,a.append(l,c,h,f);let u=te("div","task init");u.appendChild(te("h3","","Initial pose"));let m=In("Set initial pose: click the map"),g=te("p","muted",`publishes geometry_msgs/msg/PoseWithCovarianceStamped on ${o}initialpose`);u.append(m,g);let v=te("div","task svc");v.appendChild(te("h3","","Call a service"));let d=te("select"),p=te("form","svcform"),x=te("div","svcout"),A=te("p","muted","Listing the services you may call…");v.append(d,A,p,x),n.append(a,u,v);let S="goal",C=null,T=null,_=!1,w=!1;i.onClick=async(R,G)=>{if(S==="init"){if(S="goal",m.classList.remove("armed"),!w)return;let B=s()?.yaw??0;e.publish(`${o}initialpose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{pose:{position:{x:R,y:G,z:0},orientation:{x:0,y:0,z:Math.sin(B/2),w:Math.cos(B/2)}},covariance:new Array(36).fill(0)}},L=>Or(m,"initialpose",L,g)),g.textContent=`initial pose sent: (${Ht(R,2)}, ${Ht(G,2)})`;return}T?U(R,G):_&&(i.goal={x:R,y:G},i.invalidate(),e.publish(`${o}goal_pose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{position:{x:R,y:G,z:0},orientation:{x:0,y:0,z:0,w:1}}},B=>Or(a,"goal",B,l)),h.textContent=`goal published on ${o}goal_pose: (${Ht(R,2)}, ${Ht(G,2)})`)};function U(R,G){if(!T)return;let B=T;i.goal={x:R,y:G},i.invalidate();let L=s(),z=L?Math.hypot(L.x-R,L.y-G):1;c.value=0,h.textContent=`goal (${Ht(R,2)}, ${Ht(G,2)}) sent to ${B.name}…`;let q=e.sendGoal(B.name,B.type,{x:R,y:G},O=>{if(C!==q)return;let re=Number(O?.distance_remaining);It.feedback.push(re),It.feedback.length>500&&It.feedback.splice(0,250),Jn("feedback"),Number.isFinite(re)&&(c.value=z>0?Math.max(0,Math.min(1,1-re/z)):1,h.textContent=`driving to (${Ht(R,2)}, ${Ht(G,2)}): ${Ht(re,2)} m to go`)});C=q,f.disabled=!1,q.result.then(O=>{if(It.lastResult=O,C!==q)return;let re=O.status===4?"reached":O.status===5?"canceled":O.status===6?"aborted":`ended (status ${O.status})`,X=O.values??{};h.textContent=`goal ${re}${X.x!=null?` at (${Ht(X.x,2)}, ${Ht(X.y,2)})`:""}`,O.status===4&&(c.value=1),f.disabled=!0,C=null},O=>{C===q&&(C=null,f.disabled=!0,O instanceof Vs&&/not allowed/.test(O.message)?Or(a,"navigate",O.message,l):h.textContent=`goal failed: ${O.message}`)})}f.addEventListener("click",()=>{C?.cancel(),h.textContent+=" · cancel requested"}),m.addEventListener("click",()=>{S=S==="init"?"goal":"init",m.classList.toggle("armed",S==="init")}),r.push(()=>C?.cancel()),(async()=>{let[R,G]=await Promise.all([e.call("/rosapi/action_servers").then(O=>O.action_servers??[],()=>[]),e.call("/rosapi/services").then(O=>O.services??[],()=>[])]),B=R.filter(O=>O.startsWith(o)),L=B.find(O=>/navigate/.test(O))??B[0];if(L){let O=await e.call("/rosapi/service_type",{service:L}).then(re=>String(re.type??""),()=>"");T={name:L,type:O},l.textContent=`Click on the map to send a goal to ${L} (${O}).`}else{let O=await e.advertise(`${o}goal_pose`,"geometry_msgs/msg/PoseStamped");O?Or(f,"navigate",`the hub lists no navigation action you may use on ${t}, and refused the goal topic: ${O}`,l):(_=!0,r.push(()=>e.unadvertise(`${o}goal_pose`)),l.textContent=`No navigation action listed for you; clicks publish a PoseStamped on ${o}goal_pose.`)}let z=await e.advertise(`${o}initialpose`,"geometry_msgs/msg/PoseWithCovarianceStamped");z?Or(m,"initialpose",z,g):(w=!0,r.push(()=>e.unadvertise(`${o}initialpose`)));let q=G.filter(O=>O.startsWith(o));if(q.length===0){Or(d,"services",`the hub lists no services of ${t} you may call (/rosapi/services)`,A);return}for(let O of q)d.appendChild(new Option(O,O));A.textContent="",d.addEventListener("change",()=>N(d.value)),N(q[0])})();async function N(R){p.replaceChildren(te("p","muted","loading the request type…")),x.replaceChildren();let G="",B=[];try{G=String((await e.call("/rosapi/service_type",{service:R})).type),B=(await e.call("/rosapi/service_request_details",{type:G})).typedefs??[]}catch(re){p.replaceChildren(te("p","why",`cannot read the type of ${R}: ${re.message}`));return}let L=Vp(B);p.replaceChildren(te("div","muted",`${G} request`));let z=[],q=(re,X,$)=>{X&&X.fieldnames.forEach((W,ne)=>{let le=X.fieldtypes[ne],Q=B.find(be=>be.type===le);if(Q&&X.fieldarraylen[ne]===-1)return q(re[W],Q,[...$,W]);let me=te("label","",`${[...$,W].join(".")} (${le}${X.fieldarraylen[ne]>=0?"[]":""})`),pe=te("input");pe.name=[...$,W].join("."),le==="bool"&&X.fieldarraylen[ne]===-1?pe.type="checkbox":pe.value=JSON.stringify(re[W]),me.appendChild(pe),p.appendChild(me),z.push({path:[...$,W],input:pe,kind:le==="bool"&&X.fieldarraylen[ne]===-1?"bool":le==="string"&&X.fieldarraylen[ne]===-1?"string":"json"})})};q(L,B[0],[]),z.length===0&&p.appendChild(te("p","muted","(no request fields)"));for(let re of z)re.kind==="string"&&(re.input.value="");let O=In("Call","primary");O.type="submit",p.appendChild(O),p.onsubmit=async re=>{re.preventDefault();let X=structuredClone(L);try{for(let $ of z){let W=X;for(let le of $.path.slice(0,-1))W=W[le];let ne=$.path[$.path.length-1];W[ne]=$.kind==="bool"?$.input.checked:$.kind==="string"?$.input.value:JSON.parse($.input.value||"null")}}catch($){x.replaceChildren(te("p","why",`bad value: ${$.message}`));return}O.disabled=!0,x.replaceChildren(te("p","muted",`calling ${R}…`));try{let $=await e.call(R,X,10);It.lastServiceResponse={service:R,ok:!0,values:$},Jn("service-response"),x.replaceChildren(te("div","ok","response:"),Jr($))}catch($){It.lastServiceResponse={service:R,ok:!1,error:$.message},x.replaceChildren(te("p","why",`refused or failed: ${$.message}`)),$ instanceof Vs&&/not allowed/.test($.message)&&Or(O,`call:${R}`,$.message,A)}finally{It.disabled[`call:${R}`]||(O.disabled=!1)}}}}function Cs(n,e,t=""){let i=te("section",`panel ${t}`),s=te("h2","",e),r=te("span","info");s.appendChild(r);let o=te("div","body");return i.append(s,o),n.appendChild(i),{box:i,body:o,info:r}}var Ld=class{n=0;lastLatency=NaN;note(e){this.n++;let t=Rl(e?.header);t!=null&&(this.lastLatency=Date.now()-t)}};function w_(n,e,t){n.innerHTML="";let i=[],s=new Map,r=B=>{let L=s.get(B);return L||s.set(B,L=new Ld),L},o=te("div","robot-title");o.append(te("a","back","← fleet"),te("h1","",t),te("span","badge","…")),o.firstChild.href="#/",n.appendChild(o);let a=o.lastChild,l=te("div","robot-grid");n.appendChild(l);let c=Cs(l,"Map (odometry path, scan, markers, goal)","wide"),h=new jr(c.body);h.selected=t,h.canvas.id="robot-map",It.mapToScreen=(B,L)=>h.toScreen(B,L),i.push(()=>h.destroy(),()=>It.mapToScreen=null);let f=Cs(l,"Tasking","tasking"),u=Cs(l,"Laser scan"),m=Cs(l,"Point cloud (3D)"),g=Cs(l,"Camera"),v=Cs(l,"Topics","full"),d=Cs(l,"Inspector","inspector"),p=Cs(l,"Link quality (last 5 minutes)","wide"),x=Cs(l,"Configuration","full config");It.config={loaded:!1,mayChange:!1,overlay:null,result:""},i.push(S_(x.body,x.info,t,It.config));let A=null,S=!1;function C(B){S=!0;let L=B.filter(fe=>fe.name.startsWith(`/${t}/`)),z=fe=>L.filter(ke=>ke.type===fe),q="#2f80ed",O=Tu(t,B),re=z("nav_msgs/msg/Odometry")[0];for(let fe of[O,re&&{topic:re.name,type:re.type}])fe&&i.push(e.subscribe(fe.topic,ke=>{if(r(fe.topic).note(ke),fe.topic===re?.name&&Jn("odom"),fe.topic!==O?.topic)return;let Ze=Cl(ke);Ze&&(A=Ze,h.setPose(t,Ze,q),It.poses[t]={...Ze,at:Date.now()},Jn("pose"))},{type:fe.type,throttle_rate:50,queue_length:1,compression:"none"}));O||(c.info.textContent="no pose or odometry topic");let X=[...z("visualization_msgs/msg/MarkerArray"),...z("visualization_msgs/msg/Marker")];for(let fe of X){let ke=new Il;h.markers.push(ke),i.push(e.subscribe(fe.name,Ze=>{r(fe.name).note(Array.isArray(Ze?.markers)?Ze.markers[0]:Ze),ke.apply(Ze,performance.now()),h.invalidate(),Jn("markers")},{type:fe.type,queue_length:10}))}O&&(c.info.textContent=`${O.topic}${X.length?` · markers: ${X.map(fe=>fe.name).join(", ")}`:""}`);let $=z("sensor_msgs/msg/LaserScan")[0];if($){let fe=te("canvas","scan");u.body.appendChild(fe);let ke=null,Ze=10,Rt=!1;i.push(e.subscribe($.name,et=>{if(r($.name).note(et),ke=zp(et),Ze=et.range_max||Ze,Rt=!0,Jn("scan"),A){let Ct=Math.cos(A.yaw),ut=Math.sin(A.yaw),ft=new Float32Array(ke.length);for(let F=0;F<ke.length;F+=2)ft[F]=A.x+Ct*ke[F]-ut*ke[F+1],ft[F+1]=A.y+ut*ke[F]+Ct*ke[F+1];h.scan=ft,h.invalidate()}},{type:$.type,queue_length:1}));let wt=0,Vt=()=>{if(wt=requestAnimationFrame(Vt),!Rt||!ke)return;Rt=!1;let et=devicePixelRatio||1,Ct=fe.clientWidth,ut=fe.clientHeight;fe.width=Ct*et,fe.height=ut*et;let ft=fe.getContext("2d");ft.setTransform(et,0,0,et,0,0),ft.fillStyle="#0b1016",ft.fillRect(0,0,Ct,ut);let F=Math.min(Ct,ut)/2/Math.min(Ze,15);ft.strokeStyle="#1f2a35";for(let ge=2;ge<=14;ge+=2)ft.beginPath(),ft.arc(Ct/2,ut/2,ge*F,0,7),ft.stroke();ft.fillStyle="#f2c94c";for(let ge=0;ge<ke.length;ge+=2)ft.fillRect(Ct/2-ke[ge+1]*F-1,ut/2-ke[ge]*F-1,2,2);ft.fillStyle="#2f80ed",ft.beginPath(),ft.moveTo(Ct/2,ut/2-10),ft.lineTo(Ct/2-6,ut/2+6),ft.lineTo(Ct/2+6,ut/2+6),ft.fill(),u.info.textContent=`${$.name} · ${ke.length/2} points · 2 m rings`};wt=requestAnimationFrame(Vt),i.push(()=>cancelAnimationFrame(wt))}else u.body.appendChild(te("p","muted","This robot publishes no LaserScan."));let W=z("sensor_msgs/msg/PointCloud2")[0];if(W){let fe=new Yh(m.body),ke=te("select");for(let Ze of["height","intensity"])ke.appendChild(new Option(`colour by ${Ze}`,Ze));ke.addEventListener("change",()=>fe.colourBy=ke.value),m.box.querySelector("h2").appendChild(ke),fe.onShown=Ze=>{Ze!=null&&It.cloudAgesMs.push(Date.now()-Ze),It.cloudAgesMs.length>2e3&&It.cloudAgesMs.splice(0,1e3),Jn("cloud-rendered")},i.push(e.subscribe(W.name,Ze=>{r(W.name).note(Ze);let Rt=fe.show(Ze);Jn("cloud"),m.info.textContent=`${W.name} · ${Rt.toLocaleString()} points`},{type:W.type,queue_length:1})),i.push(()=>fe.destroy())}else m.body.appendChild(te("p","muted","This robot publishes no PointCloud2."));let ne=z("sensor_msgs/msg/CompressedImage")[0];if(ne){let fe=te("img","camera"),ke=te("canvas","camera bytes"),Ze=te("p","muted");g.body.append(fe,ke,Ze);let Rt="",wt=!1;i.push(e.subscribe(ne.name,async Vt=>{if(r(ne.name).note(Vt),Jn("camera"),wt)return;wt=!0;let et=wu(Vt.data),Ct=Hp(et);try{let ut=new Blob([et],{type:`image/${Ct==="png"?"png":"jpeg"}`});(await createImageBitmap(ut)).close(),Rt&&URL.revokeObjectURL(Rt),Rt=URL.createObjectURL(ut),fe.src=Rt,fe.style.display="",ke.style.display="none",Ze.textContent="",g.info.textContent=`${ne.name} · ${Vt.format} · ${(et.length/1024).toFixed(0)} KiB`}catch{fe.style.display="none",ke.style.display="";let ut=Math.max(1,Math.floor(Math.sqrt(et.length)));ke.width=ut,ke.height=ut;let ft=ke.getContext("2d"),F=ft.createImageData(ut,ut);for(let ge=0;ge<ut*ut;ge++){let Ke=et[ge];F.data[ge*4]=F.data[ge*4+1]=F.data[ge*4+2]=Ke,F.data[ge*4+3]=255}ft.putImageData(F,0,0),Ze.textContent=`not a decodable ${Vt.format} image (${Ct==="unknown"?"no image header":`${Ct} header, undecodable body`}): showing its ${et.length.toLocaleString()} bytes as grey levels`,g.info.textContent=`${ne.name} · ${Vt.format} · ${(et.length/1024).toFixed(0)} KiB`}finally{wt=!1}},{type:ne.type,queue_length:1})),i.push(()=>Rt&&URL.revokeObjectURL(Rt))}else g.body.appendChild(te("p","muted","This robot publishes no CompressedImage."));let le=te("select"),Q=te("div","tree");d.body.append(le,Q);let me=new Set([$?.name,W?.name,ne?.name,O?.topic,...X.map(fe=>fe.name),...z("foxglove_msgs/msg/CompressedVideo").map(fe=>fe.name)]),pe=L.find(fe=>!me.has(fe.name)&&fe.rate_hz>0)??L.find(fe=>!me.has(fe.name))??L[0];for(let fe of L)le.appendChild(new Option(`${fe.name} (${fe.type})`,fe.name));pe&&(le.value=pe.name);let be=null,xe=null,We=0,Qe=0,Ne=performance.now(),qe=()=>{be?.();let fe=L.find(ke=>ke.name===le.value);fe&&(Qe=0,Ne=performance.now(),xe=null,Q.textContent="waiting for a message…",be=e.subscribe(fe.name,(ke,Ze,Rt)=>{r(fe.name).note(ke),xe=ke,We=Rt,Qe++,Jn("inspector")},{type:fe.type,queue_length:1,throttle_rate:200}))};le.addEventListener("change",qe),qe();let tt=window.setInterval(()=>{if(!xe)return;let fe=Qe/((performance.now()-Ne)/1e3),ke=r(le.value).lastLatency;d.info.textContent=`${Ht(fe)} msg/s shown · latency ${Ht(ke,0)} ms · ${Math.round(performance.now()-We)} ms ago`,Q.replaceChildren(Jr(Al(xe),le.value))},1e3);i.push(()=>{clearInterval(tt),be?.()}),M_(f.body,e,t,h,()=>A,i)}let T=te("table","topics");T.innerHTML="<thead><tr><th>topic</th><th>type</th><th>rate (hub)</th><th>bandwidth (hub)</th><th>latency (here)</th><th>drops</th></tr></thead>";let _=te("tbody");T.appendChild(_),v.body.appendChild(T);let w=new Map,U=new wr(3,300),N=new $l(p.body,U,[{label:"RTT ms",colour:"#f2994a",scale:"ms"},{label:"latency ms",colour:"#eb5757",scale:"ms"},{label:"link MB/s",colour:"#27ae60",scale:"r"}],Math.max(400,p.body.clientWidth||900),180);i.push(()=>N.destroy());async function R(){let B,L;try{[{robots:B},{topics:L}]=await Promise.all([gn("/api/v1/robots"),gn("/api/v1/topics")])}catch(W){a.textContent=`cannot read the hub: ${W.message}`;return}let z=B.find(W=>W.name===t);a.textContent=z?z.online?"online":"offline":"not visible to you",a.className=`badge ${z?.online?"ok":"off"}`,n.classList.toggle("offline",!!z&&!z.online),!S&&z?.online&&C(L);let q=Date.now()/1e3;z?.online&&U.push(q,z.rtt_ms??null,z.latency_ms??null,z.link_rate_bps!=null?z.link_rate_bps/1e6:null);let O=z?.budget,re=O?[O.max_bps!=null?`${ai(O.max_bps)}`:"",O.day_bytes!=null?`${Ht(O.day_bytes/1e6,0)} MB/day`:""].filter(W=>W):[];p.info.textContent=O?` · budget ${re.join(" and ")}: using ${ai(O.use_bps)}${O.thinned.length?`, thinning ${O.thinned.length} topic${O.thinned.length>1?"s":""}`:""}`:"";let X=z?.link_estimate_age_s;z?.online&&X!=null&&X>=10?p.info.textContent+=` · capacity ${z.capacity_bps?ai(z.capacity_bps):"not known"}, measured ${_r(Date.now()-X*1e3)} (idle since)`:z?.online&&X==null&&(p.info.textContent+=" · link capacity not measured with data yet");let $=z?.mirrors??[];p.info.textContent+=$.map(W=>{let ne=z?.capacity_bps?` of ${ai(z.capacity_bps)}`:"",le=W.offload.fits===null?"link capacity not known yet":W.offload.fits?"fits the link: offload":"does not fit the link";return` · mirror ${W.name} reads ${W.reads.length} topic${W.reads.length===1?"":"s"}, ${ai(W.inputs_bps)}${ne}: ${le}`}).join(""),p.info.title=$.length?$[0].offload.rule:"",N.update();for(let W of L.filter(ne=>ne.name.startsWith(`/${t}/`))){let ne=w.get(W.name);if(!ne){let Ne=te("tr"),qe=Array.from({length:6},()=>te("td")),tt=te("span","",W.name);qe[0].append(tt),qe[1].textContent=W.type,Ne.append(...qe),_.appendChild(Ne);let fe=[new wr(1,120),new wr(1,120),new wr(1,120)];ne={name:tt,cell:qe[0],pull:null,rate:new co(qe[2],fe[0],"#2f80ed"),bw:new co(qe[3],fe[1],"#27ae60"),lat:new co(qe[4],fe[2],"#eb5757"),s:fe,drops:qe[5]},w.set(W.name,ne)}let le=W.state==="idle"||W.state==="pull"?W.state:W.thinned?"thinned":"";if(ne.name.textContent=le?`${W.name} (${le})`:W.name,ne.name.title=W.state==="idle"?"nobody is subscribed: the robot holds this topic back":W.state==="pull"?"sent only when asked: one message per pull":W.thinned?"the robot's data budget holds this topic back (lowest priorities first)":"",W.state==="pull"&&!ne.pull){let Ne=te("div","pulled"),qe=W.name,tt=In("pull","small",async()=>{tt.disabled=!0;try{let fe=qe.slice(t.length+2),ke=await gn(`/api/v1/robots/${encodeURIComponent(t)}/topics/${fe}/pull`,{method:"POST"});Ne.replaceChildren(Jr(ke.msg,qe))}catch(fe){Ne.textContent=`pull failed: ${fe.message}`}finally{tt.disabled=!1}});ne.cell.append(" ",tt,Ne),ne.pull=tt}let Q=s.get(W.name)?.lastLatency??NaN;ne.s[0].push(q,W.rate_hz),ne.s[1].push(q,W.bandwidth_bps),ne.s[2].push(q,Number.isFinite(Q)?Q:null);let me=W.offered_rate_hz,pe=W.predicted_rate_hz,be=me!=null&&pe!=null&&pe<me*.98;ne.rate.update(be?`${Ht(W.rate_hz)} Hz · link carries ~${Ht(pe)} of ${Ht(me)} offered`:`${Ht(W.rate_hz)} Hz`),ne.cell.parentElement?.children[2]?.setAttribute("title",me==null?"":`offered on the robot: ${Ht(me)} Hz`+(pe==null?"":`; predicted over its link: ${Ht(pe)} Hz`));let xe=W.compression_ratio??1;ne.bw.update(xe>=1.05&&W.link_bandwidth_bps!=null?`${ai(W.bandwidth_bps)} · link ${ai(W.link_bandwidth_bps)} (${Ht(xe,1)}×)`:ai(W.bandwidth_bps)),ne.lat.update(Number.isFinite(Q)?`${Ht(Q,0)} ms`:"not subscribed");let We=Object.entries(W.drops??{}).filter(([,Ne])=>Ne).map(([Ne,qe])=>`${Ne} ${qe}`),Qe=Object.entries(W.robot_drops??{}).filter(([,Ne])=>Ne).map(([Ne,qe])=>`${Ne} ${qe}`);ne.drops.textContent=[...We,...Qe.length?[`on the robot: ${Qe.join(", ")}`]:[]].join("; ")||"0"}}R();let G=window.setInterval(R,1e3);return i.push(()=>clearInterval(G),()=>w.forEach(B=>{B.rate.destroy(),B.bw.destroy(),B.lat.destroy()})),()=>i.forEach(B=>B())}var Hi=n=>document.getElementById(n),nl=Hi("main"),E_=Hi("conn"),mT=Hi("who"),T_=Hi("signin"),A_=Hi("signout"),Nd=Hi("estop"),Dd=Hi("estop-note"),Ud=Hi("login");function R_(){try{let n=JSON.parse(localStorage.getItem("fleetlink.estop")??"null");if(n?.topic&&n?.type)return n}catch{}return{topic:"/fleet/estop",type:"std_msgs/msg/Bool"}}var cr,il=()=>{};function Od(){cr?.close(),cr=new El(Si.wsUrl()),globalThis.fleetlinkRosbridge=cr,cr.onState=(e,t)=>{E_.textContent=e==="open"?"connected":e==="connecting"?"connecting…":`disconnected (${t}), retrying`,E_.className=`conn ${e}`,e==="open"&&gT()};let n=Si.principal();mT.textContent=n==="token"?"signed in with a token":n?`signed in as ${n}`:"anonymous (read-only where the hub allows)",T_.hidden=!!n,A_.hidden=!n}async function gT(){let n=R_(),e=await cr.advertise(n.topic,n.type);Nd.disabled=!!e,Nd.title=e?`Disabled: ${e}`:`publishes ${n.type} {data: true} on ${n.topic}`,Dd.textContent=e?`e-stop disabled: ${e}`:`→ ${n.topic}`,e?It.disabled.estop=e:delete It.disabled.estop}Nd.addEventListener("click",()=>{let n=R_(),e=n.type.endsWith("/Bool")?{data:!0}:{};for(let t=0;t<3;t++)setTimeout(()=>cr.publish(n.topic,e,i=>Dd.textContent=`e-stop refused: ${i}`),t*100);Dd.textContent=`e-stop sent on ${n.topic} at ${new Date().toLocaleTimeString()}`});function Zh(){il();let n=location.hash.replace(/^#\/?/,"");document.querySelectorAll("nav a").forEach(e=>e.classList.toggle("active",e.hash===`#/${n.split("/")[0]}`)),nl.classList.remove("offline"),n.startsWith("robot/")?il=w_(nl,cr,decodeURIComponent(n.slice(6))):n==="admin"?il=Op(nl):n==="recordings"?il=Bp(nl):il=Jp(nl,cr,e=>location.hash=`#/robot/${encodeURIComponent(e)}`)}T_.addEventListener("click",()=>Ud.showModal());Hi("login-cancel").addEventListener("click",()=>Ud.close());Hi("login-form").addEventListener("submit",async n=>{n.preventDefault();let e=n.target,t=e.elements.namedItem("user").value,i=e.elements.namedItem("password").value,s=e.elements.namedItem("token").value.trim(),r=Hi("login-error");r.textContent="";try{if(s){let o=await fetch("/api/v1/robots",{headers:{Authorization:`Bearer ${s}`}});if(!o.ok)throw new dr(o.status,(await o.json().catch(()=>null))?.error??`HTTP ${o.status}`);Si.set(s,"token")}else{let o=await gn("/api/v1/login",{method:"POST",body:JSON.stringify({user:t,password:i})});Si.set(o.token,o.principal)}e.reset(),Ud.close(),Od(),Zh()}catch(o){r.textContent=`sign-in refused: ${o.message}`}});A_.addEventListener("click",async()=>{Si.principal()!=="token"&&await gn("/api/v1/logout",{method:"POST"}).catch(()=>{}),Si.clear(),Od(),Zh()});window.addEventListener("hashchange",Zh);Od();Zh();var C_=()=>{It.renders++,requestAnimationFrame(C_)};requestAnimationFrame(C_);
